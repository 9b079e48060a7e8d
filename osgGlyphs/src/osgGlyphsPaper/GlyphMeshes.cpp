#include "GlyphMeshes.h"

#include <cmath>

using namespace osgGlyphs;
using namespace osgGlyphsPaper;
using namespace osgGlyphsPaper::detail;

namespace
{

const float PI = 3.14159265358979f;

class MeshBuilder
{
public:
    MeshBuilder() : _mesh{new osg::Vec3Array, new osg::Vec3Array, new osg::DrawElementsUInt(GL_TRIANGLES)} {}

    unsigned int vertex(const osg::Vec3& position, const osg::Vec3& normal)
    {
        _mesh.vertices->push_back(position);
        osg::Vec3 unit = normal;
        unit.normalize();
        _mesh.normals->push_back(unit);
        return _mesh.vertices->size() - 1;
    }

    void triangle(unsigned int a, unsigned int b, unsigned int c)
    {
        _mesh.triangles->push_back(a);
        _mesh.triangles->push_back(b);
        _mesh.triangles->push_back(c);
    }

    /** The side of a truncated cone about z: radius r0 at z0 to r1 at z1. */
    void side(float z0, float r0, float z1, float r1, unsigned int slices)
    {
        const float slope = (r0 - r1) / (z1 - z0); // the normal leans up where the side narrows
        const unsigned int first = _mesh.vertices->size();
        for (unsigned int i = 0; i <= slices; ++i)
        {
            const float angle = 2.0f * PI * float(i) / float(slices);
            const osg::Vec3 radial(std::cos(angle), std::sin(angle), 0.0f);
            const osg::Vec3 normal = radial + osg::Vec3(0.0f, 0.0f, slope);
            vertex(radial * r0 + osg::Vec3(0.0f, 0.0f, z0), normal);
            vertex(radial * r1 + osg::Vec3(0.0f, 0.0f, z1), normal);
        }
        for (unsigned int i = 0; i < slices; ++i)
        {
            const unsigned int a = first + 2 * i;
            triangle(a, a + 2, a + 1);
            triangle(a + 1, a + 2, a + 3);
        }
    }

    /** A disc at height z facing up (+1) or down (-1). */
    void disc(float z, float radius, float facing, unsigned int slices)
    {
        const osg::Vec3 normal(0.0f, 0.0f, facing);
        const unsigned int center = vertex(osg::Vec3(0.0f, 0.0f, z), normal);
        for (unsigned int i = 0; i <= slices; ++i)
        {
            const float angle = 2.0f * PI * float(i) / float(slices);
            vertex(osg::Vec3(std::cos(angle) * radius, std::sin(angle) * radius, z), normal);
        }
        for (unsigned int i = 0; i < slices; ++i)
        {
            if (facing > 0.0f)
                triangle(center, center + 1 + i, center + 2 + i);
            else
                triangle(center, center + 2 + i, center + 1 + i);
        }
    }

    void sphere(unsigned int slices, unsigned int stacks)
    {
        const unsigned int first = _mesh.vertices->size();
        for (unsigned int j = 0; j <= stacks; ++j)
        {
            const float polar = PI * float(j) / float(stacks);
            for (unsigned int i = 0; i <= slices; ++i)
            {
                const float angle = 2.0f * PI * float(i) / float(slices);
                const osg::Vec3 p(std::sin(polar) * std::cos(angle), std::sin(polar) * std::sin(angle),
                                  std::cos(polar));
                vertex(p, p);
            }
        }
        for (unsigned int j = 0; j < stacks; ++j)
        {
            for (unsigned int i = 0; i < slices; ++i)
            {
                const unsigned int a = first + j * (slices + 1) + i, b = a + slices + 1;
                triangle(a, b, a + 1);
                triangle(a + 1, b, b + 1);
            }
        }
    }

    GlyphMesh take() { return _mesh; }

private:
    GlyphMesh _mesh;
};

}

GlyphMesh osgGlyphsPaper::detail::createGlyphMesh(GlyphShape shape, unsigned int slices, unsigned int stacks,
                                                  float headLength, float headRadius)
{
    slices = std::max(slices, 3u);
    stacks = std::max(stacks, 2u);
    MeshBuilder builder;
    switch (shape)
    {
    case GlyphShape::Sphere:
    case GlyphShape::Ellipsoid:
    case GlyphShape::Superquadric: // neither drawn by the paper's techniques (supportsShape)
        builder.sphere(slices, stacks);
        break;
    case GlyphShape::Cone:
        builder.side(0.0f, 1.0f, 1.0f, 0.0f, slices);
        builder.disc(0.0f, 1.0f, -1.0f, slices);
        break;
    case GlyphShape::Cylinder:
        builder.side(0.0f, 1.0f, 1.0f, 1.0f, slices);
        builder.disc(0.0f, 1.0f, -1.0f, slices);
        builder.disc(1.0f, 1.0f, 1.0f, slices);
        break;
    case GlyphShape::Arrow:
    {
        const float headStart = 1.0f - headLength;
        builder.side(0.0f, 1.0f, headStart, 1.0f, slices);
        builder.disc(0.0f, 1.0f, -1.0f, slices);
        builder.side(headStart, headRadius, 1.0f, 0.0f, slices);
        builder.disc(headStart, headRadius, -1.0f, slices);
        break;
    }
    }
    return builder.take();
}
