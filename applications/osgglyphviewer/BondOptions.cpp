#include "BondOptions.h"

#include "ViewerOptions.h"

#include <osgGlyphsData/BondFinder>
#include <osgGlyphsData/BondGlyphs>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

void describeBondOptions(osg::ApplicationUsage& usage)
{
    usage.addCommandLineOption("--bond-cutoff <r>",
                               "Draw bonds between atoms at most r apart (in the positions' units), across "
                               "the faces of the frame's box where the file gives one; found again for each "
                               "frame of a trajectory. Each half of a bond is coloured as its atom.");
    usage.addCommandLineOption(
        "--bond-radius <r>", "The radius of the bonds' cylinders (default 0.4 x the smallest atom radius).");
}

bool readBondOptions(osg::ArgumentParser& arguments, BondOptions& options, std::string& error)
{
    if (arguments.read("--bond-cutoff", options.cutoff) &&
        !(options.cutoff > 0.0 && std::isfinite(options.cutoff)))
    {
        error = "--bond-cutoff needs a distance above 0";
        return false;
    }
    if (arguments.read("--bond-radius", options.radius) &&
        !(options.radius > 0.0f && std::isfinite(options.radius)))
    {
        error = "--bond-radius needs a radius above 0";
        return false;
    }
    if (options.radius > 0.0f && !options.enabled())
    {
        error = "--bond-radius needs --bond-cutoff";
        return false;
    }
    return true;
}

namespace
{

/** The box of a frame for bonds, in the coordinates of a cloud's positions (relative to its
 * origin); false where the frame has none. */
bool getBondBox(const osgGlyphsData::PointData& frame, const osg::Vec3d& origin,
                osgGlyphsData::PeriodicBox& box)
{
    if (!frame.hasBox())
        return false;
    const osg::BoundingBoxd& bounds = frame.getBox();
    box = osgGlyphsData::PeriodicBox(osg::BoundingBoxd(bounds._min - origin, bounds._max - origin),
                                     frame.getTilt());
    return true;
}

/** Finds the bonds of the atoms' current positions and refills the bond cloud, whenever the atoms
 * have moved (their positions array changed); the box from the player's frame. */
class BondUpdate : public osg::NodeCallback
{
public:
    BondUpdate(osgGlyphs::GlyphCloud* atoms, osgGlyphs::GlyphCloud* bonds,
               osgGlyphsData::TrajectoryPlayer* player, double cutoff)
        : _atoms(atoms), _bonds(bonds), _player(player), _cutoffs(cutoff)
    {
    }

    /** Finds the bonds for the atoms and the frame's box and refills the bond cloud. */
    bool refresh(const osgGlyphsData::PointData* frame, std::string& error)
    {
        const osg::Vec3Array* positions = _atoms->getPositions();
        _seen = positions;
        _seenCount = positions ? positions->getModifiedCount() : 0;
        osgGlyphsData::PeriodicBox box;
        const bool hasBox = frame && getBondBox(*frame, _atoms->getOrigin(), box);
        static const std::vector<osg::Vec3f> none;
        if (!osgGlyphsData::findBonds(positions ? positions->asVector() : none, {}, _cutoffs,
                                      hasBox ? &box : nullptr, _list, error))
            return false;
        return osgGlyphsData::updateBondCloud(*_bonds, *_atoms, _list, hasBox ? &box : nullptr, error);
    }

    std::size_t getNumBonds() const { return _list.size(); }

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        const osg::Vec3Array* positions = _atoms->getPositions();
        if (positions != _seen || (positions && positions->getModifiedCount() != _seenCount))
        {
            std::string error;
            osg::ref_ptr<const osgGlyphsData::PointData> frame;
            if (_player.valid())
                frame = _player->getCache()->getFrame(std::size_t(std::floor(_player->getPosition() + 1e-9)),
                                                      error);
            if (!refresh(frame.get(), error))
                std::cerr << PROGRAM << ": bonds: " << error << std::endl;
        }
        traverse(node, nv);
    }

private:
    osg::ref_ptr<osgGlyphs::GlyphCloud> _atoms;
    osg::ref_ptr<osgGlyphs::GlyphCloud> _bonds;
    osg::ref_ptr<osgGlyphsData::TrajectoryPlayer> _player;
    osgGlyphsData::BondCutoffs _cutoffs;
    std::vector<osgGlyphsData::Bond> _list;
    const osg::Vec3Array* _seen = nullptr;
    unsigned int _seenCount = 0;
};

}

bool addBondCloud(osg::Group& group, osgGlyphs::GlyphCloud& atoms, const osgGlyphsData::PointData& frame,
                  osgGlyphsData::TrajectoryPlayer* player, const BondOptions& options,
                  std::string& description, std::string& error)
{
    const float radius = options.radius > 0.0f ? options.radius : osgGlyphsData::getDefaultBondRadius(atoms);
    osg::ref_ptr<osgGlyphs::GlyphCloud> bonds =
        osgGlyphsData::makeBondCloud(atoms, {}, nullptr, radius, error);
    if (!bonds)
    {
        error = "--bond-radius: " + error;
        return false;
    }
    bonds->setDataVariance(osg::Object::DYNAMIC);
    osg::ref_ptr<BondUpdate> update = new BondUpdate(&atoms, bonds.get(), player, options.cutoff);
    if (!update->refresh(&frame, error))
    {
        error = frame.getSource() + ": --bond-cutoff: " + error;
        return false;
    }
    // Its own group, after the atoms': its update callback runs after the player's has moved them.
    osg::ref_ptr<osg::Group> holder = new osg::Group;
    holder->setName("bonds");
    holder->addChild(bonds.get());
    holder->setUpdateCallback(update.get());
    group.addChild(holder.get());
    std::ostringstream text;
    text << update->getNumBonds() << " bonds within " << options.cutoff
         << (frame.hasBox() ? " (periodic)" : "") << ", radius " << radius;
    description = text.str();
    return true;
}
