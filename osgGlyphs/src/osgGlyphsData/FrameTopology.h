/* osgGlyphs - private: a topology file's atoms, giving a coordinates-only trajectory (DCD, XTC,
 * TRR) their names, types and elements (FrameSourceOptions::topology). */

#ifndef OSGGLYPHS_FRAMETOPOLOGY_H
#define OSGGLYPHS_FRAMETOPOLOGY_H 1

#include <osgGlyphsData/PointData>
#include <osgGlyphsData/PointShare>

#include <functional>
#include <memory>
#include <string>

namespace osgGlyphsData
{

/** The first frame of a topology file (PDB, GRO, a LAMMPS data file, or any point file), whose
 * columns other than the per-frame ones (positions, velocities, forces, image flags) the frames of
 * a trajectory get where they lack them: the topology's atom i is the trajectory's atom i. */
class FrameTopology
{
public:
    /** Reads the topology's first frame, whole; nullptr with a one-line error naming the file. */
    static std::unique_ptr<FrameTopology> read(const std::string& path, const std::string& format,
                                               const std::function<void(const std::string&)>& warning,
                                               std::string& error);

    const std::string& getPath() const { return _path; }
    std::size_t getNumAtoms() const { return _atoms->getNumPoints(); }

    /** Adds to a frame (its share's rows, when share is not the whole) the topology's columns that
     * it lacks, with their labels and origins, and its bonds where the frame has none (the list
     * itself, shared, for the whole); a frame that has them all is left as it is. False
     * with one line naming both files and both atom counts when they disagree. trajectory and
     * frameIndex are for that message. */
    bool apply(PointData& frame, const PointShare& share, const std::string& trajectory,
               std::size_t frameIndex, std::string& error) const;

private:
    FrameTopology(const std::string& path, PointData* atoms);

    std::string _path;
    osg::ref_ptr<PointData> _atoms;
    /** The columns of _atoms that frames may get. */
    std::vector<std::string> _columns;
};

}

#endif
