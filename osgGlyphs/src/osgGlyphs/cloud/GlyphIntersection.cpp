// GlyphCloud's picking: osgUtil's intersectors meet the glyphs' exact surfaces.
#include <osgGlyphs/GlyphCloud>

#include "../picking/GlyphPicking.h"

#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>
#include <osgUtil/PolytopeIntersector>

#include <glm/geometric.hpp>

using namespace osgGlyphs;

namespace
{

/** The matrix from model coordinates (the cloud's parent's) to the intersector's coordinate
 * frame, as osgUtil's intersectors compose it in clone(). */
osg::Matrixd modelToIntersector(const osgUtil::Intersector& intersector,
                                const osgUtil::IntersectionVisitor& iv)
{
    osg::Matrixd matrix;
    switch (intersector.getCoordinateFrame())
    {
    case osgUtil::Intersector::WINDOW:
        if (iv.getWindowMatrix())
            matrix.preMult(*iv.getWindowMatrix());
        [[fallthrough]];
    case osgUtil::Intersector::PROJECTION:
        if (iv.getProjectionMatrix())
            matrix.preMult(*iv.getProjectionMatrix());
        [[fallthrough]];
    case osgUtil::Intersector::VIEW:
        if (iv.getViewMatrix())
            matrix.preMult(*iv.getViewMatrix());
        [[fallthrough]];
    case osgUtil::Intersector::MODEL:
        if (iv.getModelMatrix())
            matrix.preMult(*iv.getModelMatrix());
    }
    return matrix;
}

glm::dvec3 toGlm(const osg::Vec3d& v)
{
    return glm::dvec3(v.x(), v.y(), v.z());
}

osg::Vec3d toOsg(const glm::dvec3& v)
{
    return osg::Vec3d(v.x, v.y, v.z);
}

}

bool GlyphCloud::getGlyphSolid(unsigned int i, detail::GlyphSolid& solid) const
{
    const float radius = decodeRadius(i);
    if (radius == 0.0f)
        return false;
    const osg::Vec3 p = drawnPosition(i);
    solid.shape = _shape;
    solid.radius = radius;
    solid.base = glm::dvec3(p.x(), p.y(), p.z());
    if (hasEllipsoidShape())
    {
        osg::Vec3 semiAxes[3];
        decodeEllipsoid(i, semiAxes);
        for (int k = 0; k < 3; ++k)
            solid.semiAxes[k] = glm::dvec3(semiAxes[k].x(), semiAxes[k].y(), semiAxes[k].z());
        const osg::Vec2 exponents = decodeExponents(i);
        solid.exponents = glm::dvec2(exponents.x(), exponents.y());
        return true;
    }
    if (!hasVectorShape())
        return true;
    // decode.glsl: the axis along the vector, the tail placed by the anchor.
    const osg::Vec3& v = (*_vectors)[i];
    const glm::dvec3 vector(v.x(), v.y(), v.z());
    const double magnitude = glm::length(vector);
    solid.length = _uniformLength ? double(_lengthScale) : double(_lengthScale) * magnitude;
    if (!(magnitude > 0.0) || !(solid.length > 0.0))
        return false;
    solid.axis = vector / magnitude;
    solid.base -= solid.axis * (solid.length * getAnchorFraction(_anchor));
    solid.arrowParams = glm::dvec2(_arrowParams.x(), _arrowParams.y());
    return true;
}

std::shared_ptr<const detail::GlyphChunks> GlyphCloud::getPickingChunks() const
{
    if (_chunks)
        return _chunks;
    std::lock_guard<std::mutex> lock(_pickingMutex);
    if (!_pickingChunks)
        _pickingChunks = std::make_shared<const detail::GlyphChunks>(detail::buildGlyphChunks(
            _numGlyphs, [this](unsigned int i) { return computeGlyphBox(i); }, _cullingChunkSize));
    return _pickingChunks;
}

bool GlyphCloud::intersect(osgUtil::IntersectionVisitor& iv)
{
    osgUtil::Intersector* root = iv.getIntersector();
    if (!root)
        return false;
    std::vector<osgUtil::Intersector*> intersectors{root};
    for (size_t k = 0; k < intersectors.size(); ++k)
        if (auto* group = dynamic_cast<osgUtil::IntersectorGroup*>(intersectors[k]))
            for (const osg::ref_ptr<osgUtil::Intersector>& member : group->getIntersectors())
                intersectors.push_back(member.get());
    std::vector<osgUtil::Intersector*> leaves;
    for (osgUtil::Intersector* intersector : intersectors)
    {
        if (dynamic_cast<osgUtil::IntersectorGroup*>(intersector))
            continue;
        if (!dynamic_cast<osgUtil::LineSegmentIntersector*>(intersector) &&
            !dynamic_cast<osgUtil::PolytopeIntersector*>(intersector))
            return false;
        leaves.push_back(intersector);
    }
    for (osgUtil::Intersector* intersector : leaves)
        intersectWith(*intersector, iv);
    return true;
}

bool GlyphCloud::intersectWith(osgUtil::Intersector& intersector, osgUtil::IntersectionVisitor& iv)
{
    if (intersector.disabled() || intersector.reachedLimit() || _numGlyphs == 0)
        return true;
    const osgUtil::Intersector::IntersectionLimit limit = intersector.getIntersectionLimit();
    const osg::Matrixd toFrame = modelToIntersector(intersector, iv);

    if (auto* segment = dynamic_cast<osgUtil::LineSegmentIntersector*>(&intersector))
    {
        const osg::Matrixd fromFrame = osg::Matrixd::inverse(toFrame);
        const glm::dvec3 start = toGlm(segment->getStart() * fromFrame - _origin);
        const glm::dvec3 end = toGlm(segment->getEnd() * fromFrame - _origin);
        const double length = glm::length(end - start);
        if (!(length > 0.0) || !std::isfinite(length))
            return true;
        const glm::dvec3 direction = (end - start) / length;
        const bool nearestOnly = limit != osgUtil::Intersector::NO_LIMIT;
        const std::vector<detail::GlyphRayHit> hits = detail::castRayThroughChunks(
            *getPickingChunks(),
            [this](unsigned int i, detail::GlyphSolid& solid) { return getGlyphSolid(i, solid); }, start,
            direction, length, nearestOnly);
        osgUtil::LineSegmentIntersector::Intersections& found = segment->getIntersections();
        for (const detail::GlyphRayHit& glyphHit : hits)
        {
            osgUtil::LineSegmentIntersector::Intersection hit;
            hit.ratio = glyphHit.t / length;
            if (limit == osgUtil::Intersector::LIMIT_NEAREST && !found.empty())
            {
                if (hit.ratio >= found.begin()->ratio)
                    return true;
                found.clear();
            }
            hit.nodePath = iv.getNodePath();
            hit.drawable = this;
            hit.matrix = iv.getModelMatrix();
            hit.localIntersectionPoint = _origin + toOsg(start + direction * glyphHit.t);
            hit.localIntersectionNormal = osg::Vec3(toOsg(glyphHit.normal));
            hit.primitiveIndex = glyphHit.glyph;
            segment->insertIntersection(hit);
        }
        return true;
    }

    auto& polytopeIntersector = static_cast<osgUtil::PolytopeIntersector&>(intersector);
    const unsigned int mask = polytopeIntersector.getPrimitiveMask();
    if (!(mask & (osgUtil::PolytopeIntersector::POINT_PRIMITIVES |
                  osgUtil::PolytopeIntersector::TRIANGLE_PRIMITIVES)))
        return true;
    osg::Polytope polytope;
    polytope.setAndTransformProvidingInverse(polytopeIntersector.getPolytope(),
                                             osg::Matrixd::translate(_origin) * toFrame);
    osg::Plane reference = polytopeIntersector.getReferencePlane();
    reference.transformProvidingInverse(toFrame);
    std::vector<osgUtil::PolytopeIntersector::Intersection> hits;
    for (unsigned int glyph : detail::findGlyphsInPolytope(*getPickingChunks(), *_positions, polytope))
    {
        osgUtil::PolytopeIntersector::Intersection hit;
        hit.localIntersectionPoint = _origin + osg::Vec3d((*_positions)[glyph]);
        hit.distance = hit.maxDistance = reference.distance(hit.localIntersectionPoint);
        hit.numIntersectionPoints = 1;
        hit.intersectionPoints[0] = hit.localIntersectionPoint;
        hit.primitiveIndex = glyph;
        hits.push_back(hit);
    }
    if (hits.empty())
        return true;
    if (limit != osgUtil::Intersector::NO_LIMIT)
    {
        // The nearest to the reference plane stands for the cloud.
        hits.assign(1, *std::min_element(hits.begin(), hits.end()));
        osgUtil::PolytopeIntersector::Intersections& found = polytopeIntersector.getIntersections();
        if (limit == osgUtil::Intersector::LIMIT_NEAREST && !found.empty())
        {
            if (!(hits.front().distance < found.begin()->distance))
                return true;
            found.clear();
        }
    }
    for (osgUtil::PolytopeIntersector::Intersection& hit : hits)
    {
        hit.nodePath = iv.getNodePath();
        hit.drawable = this;
        hit.matrix = iv.getModelMatrix();
        polytopeIntersector.insertIntersection(hit);
    }
    return true;
}
