/* osgGlyphs - private: H5MD's connectivity (/connectivity: tuples of particles, H5MD 1.1) as the
 * frames' bond lists. Not installed. */

#ifndef OSGGLYPHS_HDF5_H5MDCONNECTIVITY_H
#define OSGGLYPHS_HDF5_H5MDCONNECTIVITY_H 1

#include "Hdf5Particles.h"

#include <memory>

namespace osgGlyphsHdf5
{
namespace detail
{

/** A list of pairs of one particle group: a dataset [pairs x 2] or a time-dependent element whose
 * value is [time x pairs x 2]. */
struct PairList
{
    Element pairs;
    /** The group (of those read) the pairs index. */
    std::size_t group = 0;
    /** Whether the values are the group's ids (it has an id element) rather than its rows. */
    bool byId = false;
    /** Pairs holding the dataset's fill value are ignored. */
    bool hasFill = false;
    int64_t fill = 0;
};

/** The lists of pairs in /connectivity that refer (particles_group; the one group read, without
 * it) to a group of groups; a warning for each element left out: tuples of more than two
 * particles (angles, dihedrals), non-integer values, another group. */
std::vector<PairList> describeConnectivity(hid_t file, const std::vector<ParticleGroup>& groups,
                                           std::vector<std::string>& warnings, const Place& place);

/** Whether the lists' bonds are the same at every step: neither a list's pairs nor the ids of a
 * group that a list names by id depend on time. */
bool isFixedConnectivity(const std::vector<PairList>& lists, const std::vector<ParticleGroup>& groups);

/** The bonds of the lists at step, between the particles of range (of the groups' rows, in order)
 * as the frame holds them (PointData::getBonds()). Throws at place naming the list and the pair
 * when a pair names a particle the group lacks, or one particle twice. */
std::shared_ptr<const osgGlyphsData::PointData::BondList>
readConnectivity(const std::vector<PairList>& lists, const std::vector<ParticleGroup>& groups, int64_t step,
                 const osgGlyphsData::PointRange& range, const Place& place);

}
}

#endif
