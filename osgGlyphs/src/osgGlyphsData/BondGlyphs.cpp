#include <osgGlyphsData/BondGlyphs>

#include "CellCoordinates.h"

#include <osgGlyphs/ColorMap>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgGlyphsData;

namespace
{

std::string describeBond(std::size_t index, const Bond& bond)
{
    return "bond " + std::to_string(index) + " (atoms " + std::to_string(bond.first) + " and " +
           std::to_string(bond.second) + ")";
}

bool checkAtoms(const Bond& bond, std::size_t index, std::size_t atoms, std::string& error)
{
    if (bond.first < atoms && bond.second < atoms)
        return true;
    error = describeBond(index, bond) + ": atom " + std::to_string(std::max(bond.first, bond.second)) +
            " is past the " + std::to_string(atoms) + " atoms";
    return false;
}

/** Fills an array of the bond cloud in place with a value per half-bond from the atoms'. */
template <class Array>
void fillPerHalf(Array& target, const Array& atoms, const std::vector<Bond>& bonds)
{
    target.resize(2 * bonds.size());
    for (std::size_t k = 0; k < bonds.size(); ++k)
    {
        target[2 * k] = atoms[bonds[k].first];
        target[2 * k + 1] = atoms[bonds[k].second];
    }
    target.dirty();
}

/** Moves each half-bond's start from its atom's centre out to where it leaves the atom's sphere
 * (BondEnds::AtAtomSurfaces). */
void startHalvesAtAtomSurfaces(const osgGlyphs::GlyphCloud& atoms, const std::vector<Bond>& bonds,
                               float bondRadius, std::vector<osg::Vec3f>& tails,
                               std::vector<osg::Vec3f>& vectors)
{
    if (atoms.getShape() != osgGlyphs::GlyphShape::Sphere)
        return;
    const osg::FloatArray* radii = atoms.getRadii();
    const double bondSquared = double(bondRadius) * double(bondRadius);
    const double margin = 0.98;
    for (std::size_t half = 0; half < tails.size(); ++half)
    {
        const Bond& bond = bonds[half / 2];
        const uint32_t atom = half % 2 == 0 ? bond.first : bond.second;
        const double radius =
            radii ? (atom < radii->size() ? double((*radii)[atom]) : 0.0) : double(atoms.getRadius());
        const double length = vectors[half].length();
        if (!(radius * radius > bondSquared) || !(length > 0.0) || !std::isfinite(length))
            continue;
        const double inset = margin * std::min(std::sqrt(radius * radius - bondSquared), length);
        tails[half] += vectors[half] * float(inset / length);
        vectors[half] *= float((length - inset) / length);
    }
}

}

bool osgGlyphsData::computeHalfBonds(const std::vector<osg::Vec3f>& positions, const std::vector<Bond>& bonds,
                                     const PeriodicBox* box, std::vector<osg::Vec3f>& tails,
                                     std::vector<osg::Vec3f>& vectors, std::string& error)
{
    for (std::size_t k = 0; k < bonds.size(); ++k)
    {
        const Bond& bond = bonds[k];
        if (!checkAtoms(bond, k, positions.size(), error))
            return false;
        if (!box && (bond.image[0] != 0 || bond.image[1] != 0 || bond.image[2] != 0))
        {
            error = describeBond(k, bond) + ": a periodic image (" + std::to_string(bond.image[0]) + " " +
                    std::to_string(bond.image[1]) + " " + std::to_string(bond.image[2]) + ") without a box";
            return false;
        }
    }
    tails.resize(2 * bonds.size());
    vectors.resize(2 * bonds.size());
    for (std::size_t k = 0; k < bonds.size(); ++k)
    {
        const Bond& bond = bonds[k];
        const osg::Vec3d a(positions[bond.first]), b(positions[bond.second]);
        // The second atom's image seen from the first, and the first's image from the second, are
        // one offset apart: each half runs halfway to the other atom's image.
        const osg::Vec3d offset = box ? box->getImageOffset(bond.image) : osg::Vec3d();
        const osg::Vec3d half = (b + offset - a) * 0.5;
        tails[2 * k] = positions[bond.first];
        vectors[2 * k] = osg::Vec3f(half);
        tails[2 * k + 1] = positions[bond.second];
        vectors[2 * k + 1] = osg::Vec3f(-half);
    }
    return true;
}

bool osgGlyphsData::setNearestImages(const std::vector<osg::Vec3f>& positions, const PeriodicBox& box,
                                     std::vector<Bond>& bonds, std::string& error)
{
    const osg::Vec3d inverse(1.0 / box.lengths.x(), 1.0 / box.lengths.y(), 1.0 / box.lengths.z());
    const double limit = double(std::numeric_limits<int32_t>::max());
    for (std::size_t k = 0; k < bonds.size(); ++k)
    {
        Bond& bond = bonds[k];
        if (!checkAtoms(bond, k, positions.size(), error))
            return false;
        const osg::Vec3d d = osg::Vec3d(positions[bond.second]) - osg::Vec3d(positions[bond.first]);
        const osg::Vec3d s = detail::toCellFractional(d, box.tilt, inverse);
        if (!std::isfinite(s.x()) || !std::isfinite(s.y()) || !std::isfinite(s.z()) ||
            std::abs(s.x()) > limit || std::abs(s.y()) > limit || std::abs(s.z()) > limit)
        {
            error = describeBond(k, bond) + ": the atoms' positions are not finite within the box";
            return false;
        }
        // The image of the second atom nearest to the first: its fractional displacement rounded
        // away, from the c edge down, since a tilted edge moves the coordinates of the ones before.
        int32_t image[3] = {0, 0, 0};
        osg::Vec3d rest = d;
        for (int axis = 2; axis >= 0; --axis)
        {
            if (!box.periodic[axis])
                continue;
            const osg::Vec3d fraction = detail::toCellFractional(rest, box.tilt, inverse);
            image[axis] = -static_cast<int32_t>(std::lround(fraction[axis]));
            int32_t step[3] = {0, 0, 0};
            step[axis] = image[axis];
            rest += box.getImageOffset(step);
        }
        std::copy(image, image + 3, bond.image);
    }
    return true;
}

float osgGlyphsData::getDefaultBondRadius(const osgGlyphs::GlyphCloud& atoms)
{
    float smallest = std::numeric_limits<float>::infinity();
    if (const osg::FloatArray* radii = atoms.getRadii())
    {
        for (float radius : radii->asVector())
            if (std::isfinite(radius) && radius > 0.0f)
                smallest = std::min(smallest, radius);
    }
    else if (std::isfinite(atoms.getRadius()) && atoms.getRadius() > 0.0f)
        smallest = atoms.getRadius();
    return std::isfinite(smallest) ? 0.4f * smallest : 0.0f;
}

osg::ref_ptr<osgGlyphs::GlyphCloud> osgGlyphsData::makeBondCloud(const osgGlyphs::GlyphCloud& atoms,
                                                                 const std::vector<Bond>& bonds,
                                                                 const PeriodicBox* box, float bondRadius,
                                                                 std::string& error, BondEnds ends)
{
    if (!std::isfinite(bondRadius) || bondRadius <= 0.0f)
    {
        error = "the bond radius " + std::to_string(bondRadius) + " is not finite and positive";
        return nullptr;
    }
    osg::ref_ptr<osgGlyphs::GlyphCloud> cloud = new osgGlyphs::GlyphCloud;
    cloud->setName(atoms.getName().empty() ? std::string("bonds") : atoms.getName() + " bonds");
    cloud->setShape(osgGlyphs::GlyphShape::Cylinder);
    cloud->setAnchor(osgGlyphs::GlyphAnchor::Tail);
    cloud->setLengthScale(1.0f);
    cloud->setUniformLength(false);
    cloud->setRadius(bondRadius);
    cloud->setLit(atoms.getLit());
    cloud->setMaterial(atoms.getAmbient(), atoms.getSpecular(), atoms.getShininess());
    cloud->setOpacity(atoms.getOpacity());
    cloud->setCulling(atoms.getCulling());
    cloud->setCompressedAttributes(atoms.getCompressedAttributes());
    cloud->setVectors(new osg::Vec3Array);
    cloud->setPositions(new osg::Vec3Array);
    if (!updateBondCloud(*cloud, atoms, bonds, box, error, ends))
        return nullptr;
    return cloud;
}

bool osgGlyphsData::updateBondCloud(osgGlyphs::GlyphCloud& bondCloud, const osgGlyphs::GlyphCloud& atoms,
                                    const std::vector<Bond>& bonds, const PeriodicBox* box,
                                    std::string& error, BondEnds ends)
{
    const osg::Vec3Array* positions = atoms.getPositions();
    static const std::vector<osg::Vec3f> none;
    std::vector<osg::Vec3f> tails, vectors;
    if (!computeHalfBonds(positions ? positions->asVector() : none, bonds, box, tails, vectors, error))
        return false;
    if (ends == BondEnds::AtAtomSurfaces)
        startHalvesAtAtomSurfaces(atoms, bonds, bondCloud.getRadius(), tails, vectors);

    // The atoms' map and range first: setting them rebuilds what the cloud draws, which must not
    // happen while its arrays are refilled below.
    const std::size_t numAtoms = positions ? positions->size() : 0;
    const osg::FloatArray* scalars = atoms.getScalars();
    const bool scalarColours =
        atoms.getColorMode() == osgGlyphs::GlyphColorMode::Scalar && scalars && scalars->size() >= numAtoms;
    if (scalarColours)
    {
        if (bondCloud.getColorMap() != atoms.getColorMap())
            bondCloud.setColorMap(const_cast<osgGlyphs::ColorMap*>(atoms.getColorMap()));
        if (bondCloud.getScalarRangeIsAutomatic() ||
            bondCloud.getScalarRangeMin() != atoms.getScalarRangeMin() ||
            bondCloud.getScalarRangeMax() != atoms.getScalarRangeMax())
            bondCloud.setScalarRange(atoms.getScalarRangeMin(), atoms.getScalarRangeMax());
    }

    osg::ref_ptr<osg::Vec3Array> bondPositions = bondCloud.getPositions();
    osg::ref_ptr<osg::Vec3Array> bondVectors = bondCloud.getVectors();
    if (!bondPositions)
        bondPositions = new osg::Vec3Array;
    if (!bondVectors)
        bondVectors = new osg::Vec3Array;
    bondPositions->asVector().swap(tails);
    bondVectors->asVector().swap(vectors);
    bondPositions->dirty();
    bondVectors->dirty();
    bondCloud.setOrigin(atoms.getOrigin());

    // The atoms' colouring, per half: scalars through the atoms' map and range, or colours, or
    // the one colour. Arrays of the atoms shorter than their positions leave those glyphs to the
    // cloud's own checks; the half-bonds take the one colour then.
    const osg::Vec4ubArray* colors = atoms.getColors();
    if (scalarColours)
    {
        osg::ref_ptr<osg::FloatArray> halves = bondCloud.getScalars();
        if (!halves)
            halves = new osg::FloatArray;
        fillPerHalf(*halves, *scalars, bonds);
        if (bondCloud.getScalars() != halves.get())
            bondCloud.setScalars(halves.get());
    }
    else if (atoms.getColorMode() == osgGlyphs::GlyphColorMode::RGBA && colors && colors->size() >= numAtoms)
    {
        osg::ref_ptr<osg::Vec4ubArray> halves = bondCloud.getColors();
        if (!halves)
            halves = new osg::Vec4ubArray;
        fillPerHalf(*halves, *colors, bonds);
        if (bondCloud.getColors() != halves.get())
            bondCloud.setColors(halves.get());
    }
    else if (bondCloud.getColorMode() != osgGlyphs::GlyphColorMode::Uniform ||
             bondCloud.getColor() != atoms.getColor())
        bondCloud.setColor(atoms.getColor());

    if (bondCloud.getVectors() != bondVectors.get())
        bondCloud.setVectors(bondVectors.get());
    if (bondCloud.getPositions() != bondPositions.get())
        bondCloud.setPositions(bondPositions.get());
    bondCloud.dirtyGlyphs();
    return true;
}
