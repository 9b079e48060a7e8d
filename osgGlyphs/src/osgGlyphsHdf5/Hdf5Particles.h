/* osgGlyphs - private: groups of particles whose per-particle datasets ("elements") become the
 * columns of a frame, as H5MD, snapshots and named datasets share them. */

#ifndef OSGGLYPHS_HDF5_HDF5PARTICLES_H
#define OSGGLYPHS_HDF5_HDF5PARTICLES_H 1

#include "Hdf5Dataset.h"

#include <osgGlyphsData/PointData>
#include <osgGlyphsData/PointShare>

#include <map>

namespace osgGlyphsHdf5
{
namespace detail
{

enum class ElementKind
{
    /** x y z (2 values a particle: z is 0). */
    Position,
    /** One column a value of a particle, named by convention (vx vy vz, id, mass, name_x). */
    Numbers,
    /** H5MD's integer species: the column "type" as it is, and "species" as a category. */
    Species
};

/** A per-particle dataset: fixed (rows of particles) or time-dependent (H5MD: a value dataset
 * with the time first, and the step and time of each of its values). */
struct Element
{
    std::string name;
    DatasetInfo value;
    ElementKind kind = ElementKind::Numbers;
    bool timed = false;
    std::vector<int64_t> steps;
    bool hasTimes = false;
    std::vector<double> times;
    /** The frame's columns its values go to, one a value of a particle. */
    std::vector<std::string> columns;
    /** What the opening found wrong with it: every frame that reads it fails with this. */
    std::string problemDataset;
    std::string problem;

    std::size_t rowAxis() const { return timed ? 1 : 0; }
    hsize_t rows() const { return value.dims.size() > rowAxis() ? value.dims[rowAxis()] : 0; }
    hsize_t width() const { return value.countFrom(rowAxis() + 1); }
};

/** Particles read together: one H5MD particle group, one snapshot PartType group. */
struct ParticleGroup
{
    std::string name;
    Element position;
    std::vector<Element> elements;
    /** Values of the columns that the group has no element for (a Gadget MassTable entry);
     * other missing columns are 0. */
    std::map<std::string, double> defaults;

    hsize_t count() const { return position.rows(); }
};

/** The columns of name's element of width values a particle: x y z, vx vy vz (velocity,
 * Velocities), fx fy fz (force, Forces), ix iy iz (image), id (id, ParticleIDs), mass (mass,
 * Masses), charge (charge, Charges); otherwise name, name_x name_y name_z, or name_0 name_1 ... */
std::vector<std::string> conventionalColumns(const std::string& name, hsize_t width);

/** An element at path: a group with value and step (and time) datasets, or a dataset. Throws at
 * place naming the dataset when it is malformed; kind Position asks for 2 or 3 values a
 * particle. */
Element describeElement(hid_t file, const std::string& path, ElementKind kind, const Place& place);

/** Records a failure of describing as the element's problem, for the frames to report. */
Element brokenElement(const std::string& name, const Hdf5Error& error);

/** The index of the element's value at step, or the last before it. Throws when it has none. */
hsize_t indexAt(const Element& element, int64_t step, const Place& place);

/** The columns of the groups, in the order of their first appearance, and a warning for each
 * that some group lacks. groupColumn (when there are several groups) is added last. */
std::vector<std::string> planColumns(const std::vector<ParticleGroup>& groups, const std::string& groupColumn,
                                     const std::string& file, std::vector<std::string>& warnings);

/** Reads share of the particles of every group (concatenated in order) at step into a frame with
 * the columns of planColumns(): values of double-precision datasets keep their decimals through
 * an origin taken from the first particle's value (the same in every share); species become a
 * category; several groups get groupColumn, their names as labels. */
osg::ref_ptr<osgGlyphsData::PointData> readParticles(const std::vector<ParticleGroup>& groups,
                                                     const std::vector<std::string>& columns,
                                                     const std::string& groupColumn, int64_t step,
                                                     const osgGlyphsData::PointShare& share,
                                                     const Place& place);

}
}

#endif
