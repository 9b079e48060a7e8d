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
    usage.addCommandLineOption("--bonds",
                               "Draw the bonds the file lists (a LAMMPS data file's Bonds, PDB CONECT, those "
                               "of --topology), and make a file without them an error. They are drawn by "
                               "default where the file lists them.");
    usage.addCommandLineOption("--no-bonds", "Do not draw the bonds the file lists.");
    usage.addCommandLineOption("--bond-cutoff <r>",
                               "Draw bonds between atoms at most r apart (in the positions' units), across "
                               "the faces of the frame's box where the file gives one; found again for each "
                               "frame of a trajectory, instead of the bonds the file lists. Each half of a "
                               "bond is coloured as its atom.");
    usage.addCommandLineOption(
        "--bond-radius <r>", "The radius of the bonds' cylinders (default 0.4 x the smallest atom radius).");
}

bool readBondOptions(osg::ArgumentParser& arguments, BondOptions& options, std::string& error)
{
    options.required = arguments.read("--bonds");
    options.listed = !arguments.read("--no-bonds");
    if (options.required && !options.listed)
    {
        error = "--bonds and --no-bonds contradict each other";
        return false;
    }
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
    if (options.enabled() && options.required)
    {
        error = "--bonds draws the file's bonds, --bond-cutoff bonds by distance: give one of them";
        return false;
    }
    if (options.radius > 0.0f && !options.enabled() && !options.listed)
    {
        error = "--bond-radius with --no-bonds draws nothing";
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

/** Refills the bond cloud whenever the atoms have moved (their positions array changed): the bonds
 * found within the cutoff, or the listed ones to their nearest images; the box from the player's
 * frame. */
class BondUpdate : public osg::NodeCallback
{
public:
    /** Bonds within cutoff, or the listed ones where cutoff is 0. */
    BondUpdate(osgGlyphs::GlyphCloud* atoms, osgGlyphs::GlyphCloud* bonds,
               osgGlyphsData::TrajectoryPlayer* player, double cutoff,
               std::shared_ptr<const osgGlyphsData::PointData::BondList> listed)
        : _atoms(atoms), _bonds(bonds), _player(player), _cutoffs(cutoff), _listed(std::move(listed))
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
        const std::vector<osg::Vec3f>& atoms = positions ? positions->asVector() : none;
        if (_cutoffs.getDefaultCutoff() > 0.0)
        {
            if (!osgGlyphsData::findBonds(atoms, {}, _cutoffs, hasBox ? &box : nullptr, _list, error))
                return false;
        }
        else
        {
            _list = *_listed;
            if (hasBox && !osgGlyphsData::setNearestImages(atoms, box, _list, error))
                return false;
        }
        return osgGlyphsData::updateBondCloud(*_bonds, *_atoms, _list, hasBox ? &box : nullptr, error,
                                              osgGlyphsData::BondEnds::AtAtomSurfaces);
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
    std::shared_ptr<const osgGlyphsData::PointData::BondList> _listed;
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
    osg::ref_ptr<osgGlyphs::GlyphCloud> bonds = osgGlyphsData::makeBondCloud(
        atoms, {}, nullptr, radius, error, osgGlyphsData::BondEnds::AtAtomSurfaces);
    if (!bonds)
    {
        error = "--bond-radius: " + error;
        return false;
    }
    bonds->setDataVariance(osg::Object::DYNAMIC);
    const bool listed = !options.enabled();
    if (listed && (!frame.getBonds() || frame.getBonds()->empty()))
    {
        error = frame.getSource() + ": --bonds: the file lists no bonds (a LAMMPS data file's Bonds, PDB "
                                    "CONECT): give a --topology that does, or --bond-cutoff";
        return false;
    }
    osg::ref_ptr<BondUpdate> update =
        new BondUpdate(&atoms, bonds.get(), player, options.cutoff, listed ? frame.getBonds() : nullptr);
    if (!update->refresh(&frame, error))
    {
        error = frame.getSource() + (listed ? ": bonds: " : ": --bond-cutoff: ") + error;
        return false;
    }
    // Its own group, after the atoms': its update callback runs after the player's has moved them.
    osg::ref_ptr<osg::Group> holder = new osg::Group;
    holder->setName("bonds");
    holder->addChild(bonds.get());
    holder->setUpdateCallback(update.get());
    group.addChild(holder.get());
    std::ostringstream text;
    text << update->getNumBonds() << " bonds";
    if (listed)
        text << " listed in the file";
    else
        text << " within " << options.cutoff;
    text << (frame.hasBox() ? " (periodic)" : "") << ", radius " << radius;
    description = text.str();
    return true;
}
