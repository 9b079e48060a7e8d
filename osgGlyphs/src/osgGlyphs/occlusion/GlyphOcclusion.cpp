#include "GlyphOcclusion.h"

#include <osg/BoundingBox>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

using namespace osgGlyphs;

namespace
{

const unsigned int NUM_DIRECTIONS = 64;
const float DEFAULT_REACH_IN_RADII = 2.0f;
const unsigned int MAX_CHAIN_SPHERES = 32;
const unsigned int GLYPHS_PER_TASK = 2048;
const std::uint64_t ALL_DIRECTIONS = ~std::uint64_t(0);

/** Unit directions spread evenly over the sphere (a Fibonacci lattice), as three arrays. */
struct Directions
{
    std::array<float, NUM_DIRECTIONS> x, y, z;
    Directions()
    {
        const double golden = M_PI * (3.0 - std::sqrt(5.0));
        for (unsigned int k = 0; k < NUM_DIRECTIONS; ++k)
        {
            const double h = 1.0 - (2.0 * k + 1.0) / NUM_DIRECTIONS;
            const double ring = std::sqrt(1.0 - h * h);
            x[k] = float(ring * std::cos(golden * k));
            y[k] = float(ring * std::sin(golden * k));
            z[k] = float(h);
        }
    }
};

/** The directions inside cones, tabulated: a bit per direction for each cone axis (a cell of a
 * cube map) and each cone width (a bin of sqrt(1 - cos(half angle)), which is nearly the half
 * angle). A cone's directions are then one lookup, to within the cells' few degrees. */
class ConeMasks
{
public:
    explicit ConeMasks(const Directions& directions)
    {
        _masks.resize(6 * CELLS * CELLS * WIDTHS);
        for (int face = 0; face < 6; ++face)
            for (int i = 0; i < CELLS; ++i)
                for (int j = 0; j < CELLS; ++j)
                {
                    const glm::vec3 axis = cellAxis(face, i, j);
                    for (int w = 0; w < WIDTHS; ++w)
                    {
                        const float width = (w + 0.5f) / WIDTHS;
                        const float cosine = 1.0f - width * width;
                        std::uint64_t mask = 0;
                        for (unsigned int k = 0; k < NUM_DIRECTIONS; ++k)
                            if (directions.x[k] * axis.x + directions.y[k] * axis.y +
                                    directions.z[k] * axis.z >
                                cosine)
                                mask |= std::uint64_t(1) << k;
                        _masks[index(face, i, j, w)] = mask;
                    }
                }
    }

    /** The directions within the cone of unit axis and half angle of cosine (0 to 1). */
    std::uint64_t lookUp(const glm::vec3& axis, float cosine) const
    {
        const glm::vec3 magnitude = glm::abs(axis);
        const int major = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0
                          : magnitude.y >= magnitude.z                             ? 1
                                                                                   : 2;
        const int face = 2 * major + (axis[major] < 0.0f ? 1 : 0);
        const float u = axis[(major + 1) % 3] / magnitude[major],
                    v = axis[(major + 2) % 3] / magnitude[major];
        const int i = std::min(CELLS - 1, int((u + 1.0f) * 0.5f * CELLS));
        const int j = std::min(CELLS - 1, int((v + 1.0f) * 0.5f * CELLS));
        const int w = std::min(WIDTHS - 1, int(std::sqrt(std::max(0.0f, 1.0f - cosine)) * WIDTHS));
        return _masks[index(face, std::max(i, 0), std::max(j, 0), w)];
    }

private:
    static const int CELLS = 12;
    static const int WIDTHS = 32;

    static std::size_t index(int face, int i, int j, int w)
    {
        return ((std::size_t(face) * CELLS + i) * CELLS + j) * WIDTHS + w;
    }

    static glm::vec3 cellAxis(int face, int i, int j)
    {
        const int major = face / 2;
        glm::vec3 axis(0.0f);
        axis[major] = face % 2 ? -1.0f : 1.0f;
        axis[(major + 1) % 3] = (i + 0.5f) / CELLS * 2.0f - 1.0f;
        axis[(major + 2) % 3] = (j + 0.5f) / CELLS * 2.0f - 1.0f;
        return glm::normalize(axis);
    }

    std::vector<std::uint64_t> _masks;
};

struct Sphere
{
    float x, y, z, radius;
    unsigned int owner;
};

/** A glyph that receives occlusion: its bounding sphere, and its extent along its axis (a vector
 * glyph's half length, 0 for a sphere) and across it (its widest radius). */
struct Receiver
{
    glm::vec3 centre;
    float radius;
    glm::vec3 axis;
    float halfLength;
    float width;
    unsigned int index;

    /** Its surface point of outward normal direction (a unit vector), from its centre: a
     * sphere's; for a vector glyph, a point of normal direction on a capsule of its widest radius
     * around its axis, from the middle of the axis (normals across it) to its ends (along it). */
    glm::vec3 surfacePoint(const glm::vec3& direction) const
    {
        return axis * (halfLength * glm::dot(axis, direction)) + direction * width;
    }
};

/** The radius of a vector glyph at a distance s from its tail, along its axis (see vector.glsl). */
double profileRadius(const detail::GlyphSolid& glyph, double s)
{
    const double along = s / glyph.length;
    switch (glyph.shape)
    {
    case GlyphShape::Cone:
        return glyph.radius * (1.0 - along);
    case GlyphShape::Arrow:
    {
        const double head = glyph.arrowParams.x;
        if (along < 1.0 - head)
            return glyph.radius;
        return glyph.radius * glyph.arrowParams.y * (1.0 - along) / head;
    }
    default:
        return glyph.radius;
    }
}

/** The glyph as occluding spheres: itself, or a chain along a vector glyph's axis. */
void addOccluders(const detail::GlyphSolid& glyph, unsigned int owner, std::vector<Sphere>& spheres)
{
    if (!isVectorShape(glyph.shape))
    {
        spheres.push_back(
            {float(glyph.base.x), float(glyph.base.y), float(glyph.base.z), float(glyph.radius), owner});
        return;
    }
    const unsigned int count =
        std::clamp(unsigned(std::ceil(glyph.length / glyph.radius)), 1u, MAX_CHAIN_SPHERES);
    const double step = glyph.length / count;
    for (unsigned int j = 0; j < count; ++j)
    {
        const double s = (j + 0.5) * step;
        // Each sphere covers its slab of the solid: its radius at the slab's wide end, and half the slab.
        const double wide = std::max(profileRadius(glyph, s - 0.5 * step), profileRadius(glyph, s));
        const glm::dvec3 centre = glyph.base + glyph.axis * s;
        spheres.push_back(
            {float(centre.x), float(centre.y), float(centre.z), float(std::max(wide, 0.25 * step)), owner});
    }
}

Receiver makeReceiver(const detail::GlyphSolid& glyph, unsigned int index)
{
    const float radius = float(glyph.radius);
    if (!isVectorShape(glyph.shape))
        return {glm::vec3(glyph.base), radius, glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, radius, index};
    const double widest =
        glyph.shape == GlyphShape::Arrow ? glyph.radius * std::max(glyph.arrowParams.y, 1.0) : glyph.radius;
    const glm::dvec3 centre = glyph.base + glyph.axis * (0.5 * glyph.length);
    return {glm::vec3(centre),     float(std::hypot(0.5 * glyph.length, widest)),
            glm::vec3(glyph.axis), float(0.5 * glyph.length),
            float(widest),         index};
}

/** Items binned into the cells of a uniform grid, stored cell by cell. */
class Grid
{
public:
    Grid(const osg::BoundingBox& box, float cellSize, std::size_t items)
    {
        // At most a few cells per item, so that sparse data does not allocate an empty grid.
        const double maxCells = 4.0 * double(items) + 64.0;
        _cellSize = cellSize;
        for (;;)
        {
            for (int a = 0; a < 3; ++a)
                _dims[a] = std::max(1, int(std::ceil((box._max[a] - box._min[a]) / _cellSize)) + 1);
            if (double(_dims[0]) * _dims[1] * _dims[2] <= maxCells)
                break;
            _cellSize *= 1.5f;
        }
        _min = glm::vec3(box._min.x(), box._min.y(), box._min.z());
        _start.assign(std::size_t(_dims[0]) * _dims[1] * _dims[2] + 1, 0);
    }

    float cellSize() const { return _cellSize; }
    const glm::ivec3& dims() const { return _dims; }

    glm::ivec3 cellOf(const glm::vec3& p) const
    {
        const glm::ivec3 cell((p - _min) / _cellSize);
        return glm::clamp(cell, glm::ivec3(0), _dims - 1);
    }
    std::size_t indexOf(const glm::ivec3& cell) const
    {
        return (std::size_t(cell.z) * _dims.y + cell.y) * _dims.x + cell.x;
    }

    /** Sorts items (with a position) into the cells: returns them in cell order. */
    template <class Item, class Position>
    std::vector<Item> bin(const std::vector<Item>& items, Position position)
    {
        std::vector<std::size_t> cells(items.size());
        for (std::size_t i = 0; i < items.size(); ++i)
        {
            cells[i] = indexOf(cellOf(position(items[i])));
            ++_start[cells[i] + 1];
        }
        for (std::size_t c = 1; c < _start.size(); ++c)
            _start[c] += _start[c - 1];
        std::vector<std::size_t> next(_start.begin(), _start.end() - 1);
        std::vector<Item> sorted(items.size());
        for (std::size_t i = 0; i < items.size(); ++i)
            sorted[next[cells[i]]++] = items[i];
        return sorted;
    }

    /** The squared distance from a point to a cell's box. */
    float distance2(const glm::ivec3& cell, const glm::vec3& point) const
    {
        const glm::vec3 lo = _min + glm::vec3(cell) * _cellSize;
        const glm::vec3 outside = glm::max(glm::max(lo - point, point - (lo + _cellSize)), glm::vec3(0.0f));
        return glm::dot(outside, outside);
    }

    std::size_t begin(std::size_t cell) const { return _start[cell]; }
    std::size_t end(std::size_t cell) const { return _start[cell + 1]; }

private:
    float _cellSize = 1.0f;
    glm::ivec3 _dims = glm::ivec3(1);
    glm::vec3 _min = glm::vec3(0.0f);
    std::vector<std::size_t> _start;
};

osg::Vec4ub encode(float mean, const glm::vec3& vector)
{
    auto unit = [](float value)
    { return (unsigned char)std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f); };
    return osg::Vec4ub(unit(vector.x * 0.5f + 0.5f), unit(vector.y * 0.5f + 0.5f),
                       unit(vector.z * 0.5f + 0.5f), unit(mean));
}

/** Which directions are blocked (0 or 1 each, in ints, as the comparisons that set them). */
using Blocked = std::array<int, NUM_DIRECTIONS>;

/** A receiver's surface points facing each direction (relative to its centre), with their
 * components along the direction and their squared lengths. */
struct RayOrigins
{
    std::array<float, NUM_DIRECTIONS> x, y, z, along, squared;
};

/** Computes the occlusion of receivers from the spheres binned in the grid. */
class OcclusionSolver
{
public:
    OcclusionSolver(const Grid& grid, const std::vector<Sphere>& spheres, float reach, float widestSphere)
        : _grid(grid), _spheres(spheres), _reach(reach), _widestSphere(widestSphere), _cones(_directions)
    {
    }

    osg::Vec4ub solve(const Receiver& receiver) const
    {
        Blocked blocked{};
        std::uint64_t coneBlocked = 0;
        RayOrigins origins;
        for (unsigned int k = 0; k < NUM_DIRECTIONS; ++k)
        {
            const glm::vec3 d(_directions.x[k], _directions.y[k], _directions.z[k]);
            const glm::vec3 o = receiver.surfacePoint(d);
            origins.x[k] = o.x;
            origins.y[k] = o.y;
            origins.z[k] = o.z;
            origins.along[k] = glm::dot(o, d);
            origins.squared[k] = glm::dot(o, o);
        }
        const float limit = receiver.radius + _reach; // how far occluding surfaces count
        const float search = limit + _widestSphere;   // how far occluding centres may be
        const glm::ivec3 home = _grid.cellOf(receiver.centre);
        const int rings = int(std::ceil(search / _grid.cellSize()));
        for (int ring = 0; ring <= rings; ++ring)
        {
            forEachCellOfRing(home, ring, receiver.centre, search,
                              [&](std::size_t cell)
                              {
                                  for (std::size_t s = _grid.begin(cell); s < _grid.end(cell); ++s)
                                      block(receiver, origins, _spheres[s], limit, coneBlocked, blocked);
                              });
            if ((coneBlocked | toBits(blocked)) == ALL_DIRECTIONS)
                break;
        }
        coneBlocked |= toBits(blocked);
        float open = 0.0f;
        glm::vec3 vector(0.0f);
        for (unsigned int k = 0; k < NUM_DIRECTIONS; ++k)
        {
            const float v = (coneBlocked >> k) & 1u ? 0.0f : 1.0f;
            open += v;
            vector += v * glm::vec3(_directions.x[k], _directions.y[k], _directions.z[k]);
        }
        return encode(open / NUM_DIRECTIONS, vector * (2.0f / NUM_DIRECTIONS));
    }

private:
    /** Visits the cells of a ring around home (its cells at that Chebyshev distance) that come
     * within range of point. */
    template <class Visit>
    void forEachCellOfRing(const glm::ivec3& home, int ring, const glm::vec3& point, float range,
                           Visit visit) const
    {
        const glm::ivec3 lo = glm::max(home - ring, glm::ivec3(0));
        const glm::ivec3 hi = glm::min(home + ring, _grid.dims() - 1);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                {
                    const glm::ivec3 offset = glm::abs(glm::ivec3(x, y, z) - home);
                    if (std::max(offset.x, std::max(offset.y, offset.z)) == ring &&
                        _grid.distance2(glm::ivec3(x, y, z), point) <= range * range)
                        visit(_grid.indexOf(glm::ivec3(x, y, z)));
                }
    }

    static std::uint64_t toBits(const Blocked& blocked)
    {
        std::uint64_t bits = 0;
        for (unsigned int k = 0; k < NUM_DIRECTIONS; ++k)
            bits |= std::uint64_t(blocked[k] != 0) << k;
        return bits;
    }

    /** Marks the directions whose ray, from the receiver's surface point facing that way, meets
     * the sphere within reach (limit from the centre), or starts inside it: in coneBlocked where
     * they form a cone, in blocked otherwise. */
    void block(const Receiver& receiver, const RayOrigins& origins, const Sphere& sphere, float limit,
               std::uint64_t& coneBlocked, Blocked& blocked) const
    {
        if (sphere.owner == receiver.index)
            return;
        const glm::vec3 offset = glm::vec3(sphere.x, sphere.y, sphere.z) - receiver.centre;
        const float distance2 = glm::dot(offset, offset);
        if (distance2 > (limit + sphere.radius) * (limit + sphere.radius))
            return;
        const float apart = receiver.radius + sphere.radius;
        if (receiver.halfLength == 0.0f && distance2 >= apart * apart)
        {
            // A sphere clear of a spherical receiver: the surface rays are the rays from its centre
            // past its radius, and those that meet the sphere before limit form a cone around it,
            // out to its tangents or to the circle of the sphere at limit from the centre.
            const float tangent2 = distance2 - sphere.radius * sphere.radius;
            const float distance = std::sqrt(distance2);
            const float cosine = tangent2 <= limit * limit
                                     ? std::sqrt(tangent2) / distance
                                     : (limit * limit + tangent2) / (2.0f * limit * distance);
            coneBlocked |= _cones.lookUp(offset / distance, cosine);
            return;
        }
        const float outside = distance2 - sphere.radius * sphere.radius;
        const float reach = _reach;
        for (unsigned int k = 0; k < NUM_DIRECTIONS; ++k)
        {
            // The ray from the surface point o along d: c = |sphere - o|^2 - radius^2, and b the
            // distance along the ray to the point nearest the sphere's centre.
            const float e =
                _directions.x[k] * offset.x + _directions.y[k] * offset.y + _directions.z[k] * offset.z;
            const float f = origins.x[k] * offset.x + origins.y[k] * offset.y + origins.z[k] * offset.z;
            const float b = e - origins.along[k];
            const float c = outside - 2.0f * f + origins.squared[k];
            const float discriminant = b * b - c;
            const float beyond = b - reach;
            // Bitwise, not short-circuit: the loop runs over several directions at once.
            const int meets = int(b > 0.0f) & int(discriminant > 0.0f) &
                              (int(beyond <= 0.0f) | int(beyond * beyond <= discriminant));
            blocked[k] |= int(c < 0.0f) | meets;
        }
    }

    const Grid& _grid;
    const std::vector<Sphere>& _spheres;
    float _reach;
    float _widestSphere;
    Directions _directions;
    ConeMasks _cones;
};

}

osg::ref_ptr<osg::Vec4ubArray>
osgGlyphs::detail::computeGlyphOcclusion(unsigned int count,
                                         const std::function<bool(unsigned int, GlyphSolid&)>& solid,
                                         const GlyphOcclusionSettings& settings)
{
    osg::ref_ptr<osg::Vec4ubArray> values = new osg::Vec4ubArray;
    values->assign(count, encode(1.0f, glm::vec3(0.0f)));
    values->setNormalize(true);
    std::vector<Sphere> spheres;
    std::vector<Receiver> receivers;
    receivers.reserve(count);
    spheres.reserve(count);
    osg::BoundingBox box;
    double radiusSum = 0.0;
    float widestSphere = 0.0f;
    for (unsigned int i = 0; i < count; ++i)
    {
        GlyphSolid glyph;
        if (!solid(i, glyph))
            continue;
        receivers.push_back(makeReceiver(glyph, i));
        radiusSum += receivers.back().radius;
        const std::size_t first = spheres.size();
        addOccluders(glyph, i, spheres);
        for (std::size_t s = first; s < spheres.size(); ++s)
        {
            box.expandBy(osg::Vec3(spheres[s].x, spheres[s].y, spheres[s].z));
            widestSphere = std::max(widestSphere, spheres[s].radius);
        }
    }
    if (receivers.empty())
        return values;
    const float reach =
        settings.reach > 0.0f ? settings.reach : DEFAULT_REACH_IN_RADII * float(radiusSum / receivers.size());
    for (const Receiver& receiver : receivers)
        box.expandBy(osg::Vec3(receiver.centre.x, receiver.centre.y, receiver.centre.z));

    // Cells of half the usual search radius: a receiver looks a few rings of cells around its own.
    Grid grid(box, std::max(0.5f * (float(radiusSum / receivers.size()) + reach + widestSphere), 1e-6f),
              spheres.size());
    Grid receiverGrid = grid; // the same cells: receivers are solved cell by cell, near their occluders
    spheres = grid.bin(spheres, [](const Sphere& s) { return glm::vec3(s.x, s.y, s.z); });
    receivers = receiverGrid.bin(receivers, [](const Receiver& r) { return r.centre; });

    const OcclusionSolver solver(grid, spheres, reach, widestSphere);
    const std::size_t tasks = (receivers.size() + GLYPHS_PER_TASK - 1) / GLYPHS_PER_TASK;
    std::atomic<std::size_t> nextTask{0}, doneTasks{0};
    auto work = [&](bool reportProgress)
    {
        for (std::size_t task = nextTask++; task < tasks; task = nextTask++)
        {
            const std::size_t end = std::min(receivers.size(), (task + 1) * GLYPHS_PER_TASK);
            for (std::size_t r = task * GLYPHS_PER_TASK; r < end; ++r)
                (*values)[receivers[r].index] = solver.solve(receivers[r]);
            const std::size_t done = ++doneTasks;
            if (reportProgress && settings.progress)
                settings.progress(float(done) / float(tasks));
        }
    };
    const unsigned int threads = std::max(
        1u, std::min<unsigned int>(settings.threads ? settings.threads : std::thread::hardware_concurrency(),
                                   unsigned(tasks)));
    std::vector<std::thread> helpers;
    for (unsigned int t = 1; t < threads; ++t)
        helpers.emplace_back(work, false);
    work(true);
    for (std::thread& helper : helpers)
        helper.join();
    if (settings.progress)
        settings.progress(1.0f);
    return values;
}
