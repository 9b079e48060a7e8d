// osgglyphviewer: bonds between atoms, found by a distance cutoff and drawn as half-bond cylinders
// beside the atoms (osgGlyphsData/BondFinder, osgGlyphsData/BondGlyphs).

#ifndef OSGGLYPHVIEWER_BONDOPTIONS_H
#define OSGGLYPHVIEWER_BONDOPTIONS_H 1

#include <osgGlyphs/GlyphCloud>
#include <osgGlyphsData/PointData>
#include <osgGlyphsData/TrajectoryPlayer>

#include <osg/ApplicationUsage>
#include <osg/ArgumentParser>
#include <osg/Group>

#include <string>

/** How bonds are drawn: those the file lists (LAMMPS data Bonds, PDB CONECT, a topology's), unless
 * --no-bonds, or those within a cutoff instead. */
struct BondOptions
{
    double cutoff = 0.0;   // --bond-cutoff r: atoms at most r apart bond; 0: the file's bonds
    float radius = 0.0f;   // --bond-radius r; 0: 0.4 x the smallest atom radius
    bool listed = true;    // false: --no-bonds
    bool required = false; // --bonds: a file without a bond list is an error

    /** Bonds by distance. */
    bool enabled() const { return cutoff > 0.0; }
    /** Whether the bonds of frame are drawn. */
    bool drawsBondsOf(const osgGlyphsData::PointData& frame) const
    {
        return enabled() || (listed && (required || (frame.getBonds() && !frame.getBonds()->empty())));
    }
};

void describeBondOptions(osg::ApplicationUsage& usage);

/** Reads the options above; false with a one-line error on a bad value. */
bool readBondOptions(osg::ArgumentParser& arguments, BondOptions& options, std::string& error);

/** Adds to group, after the atoms' cloud, the bonds of the atoms of frame (whose glyphs atoms
 * holds, in the same order) as a cloud of half-bonds coloured as their atoms: the bonds the frame
 * lists, or found within the cutoff, across the faces of the frame's box where it has one
 * (periodic along every edge). With a player, the bonds follow the atoms, in the update traversal,
 * whenever the player has moved them: found again within the cutoff, or the listed bonds drawn to
 * the nearest images in the box of the frame shown. description gets a few words for the console.
 * False with a one-line error. */
bool addBondCloud(osg::Group& group, osgGlyphs::GlyphCloud& atoms, const osgGlyphsData::PointData& frame,
                  osgGlyphsData::TrajectoryPlayer* player, const BondOptions& options,
                  std::string& description, std::string& error);

#endif
