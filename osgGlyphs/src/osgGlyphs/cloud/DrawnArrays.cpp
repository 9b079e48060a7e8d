#include "DrawnArrays.h"

#include <cstring>

using namespace osgGlyphs;
using namespace osgGlyphs::detail;

void osgGlyphs::detail::gatherElements(const osg::Array& source, const std::vector<unsigned int>& ids,
                                       osg::Array& into)
{
    into.setNormalize(source.getNormalize());
    into.setPreserveDataType(source.getPreserveDataType());
    into.resizeArray(static_cast<unsigned int>(ids.size()));
    const size_t size = source.getElementSize();
    const auto* from = static_cast<const char*>(source.getDataPointer());
    auto* to = static_cast<char*>(const_cast<GLvoid*>(into.getDataPointer()));
    for (size_t k = 0; k < ids.size(); ++k)
        std::memcpy(to + k * size, from + size_t(ids[k]) * size, size);
    into.dirty();
}

void osgGlyphs::detail::permuteElements(osg::Array& array, const std::vector<unsigned int>& order)
{
    osg::ref_ptr<osg::Array> reordered = static_cast<osg::Array*>(array.cloneType());
    gatherElements(array, order, *reordered);
    std::memcpy(const_cast<GLvoid*>(array.getDataPointer()), reordered->getDataPointer(),
                size_t(order.size()) * array.getElementSize());
    array.dirty();
}

osg::Array* DrawnArrays::gather(Copy& copy, const osg::Array* source, bool orderChanged)
{
    if (!source)
    {
        copy = Copy();
        return nullptr;
    }
    const bool sameType = copy.array.valid() && copy.array->getType() == source->getType() &&
                          copy.array->getDataType() == source->getDataType();
    if (!orderChanged && sameType && copy.source == source &&
        copy.modifiedCount == source->getModifiedCount())
        return copy.array.get();
    if (!sameType)
    {
        // Bound as the technique attaches it (attachGlyphArrays), and kept so while it is refilled.
        copy.array = static_cast<osg::Array*>(source->cloneType());
        copy.array->setBinding(osg::Array::BIND_PER_VERTEX);
    }
    gatherElements(*source, _chunks->ids, *copy.array);
    copy.source = source;
    copy.modifiedCount = source->getModifiedCount();
    return copy.array.get();
}

GlyphArrays DrawnArrays::update(const GlyphArrays& source, const std::shared_ptr<const GlyphChunks>& chunks)
{
    if (chunks->isIdentity(source.count))
    {
        clear();
        return source;
    }
    // Chunks rebuilt after an edit often keep the order: then only the edited arrays are copied.
    const bool orderChanged = chunks != _chunks && (!_chunks || chunks->ids != _chunks->ids);
    _chunks = chunks;
    _reordered = true;
    GlyphArrays drawn;
    drawn.positions = gather(_positions, source.positions, orderChanged);
    drawn.radiusScalar = gather(_radiusScalar, source.radiusScalar, orderChanged);
    drawn.colors = static_cast<osg::Vec4ubArray*>(gather(_colors, source.colors, orderChanged));
    drawn.vectors = static_cast<osg::Vec3Array*>(gather(_vectors, source.vectors, orderChanged));
    drawn.occlusion = static_cast<osg::Vec4ubArray*>(gather(_occlusion, source.occlusion, orderChanged));
    drawn.axes = gather(_axes, source.axes, orderChanged);
    drawn.orientations = gather(_orientations, source.orientations, orderChanged);
    drawn.count = static_cast<unsigned int>(chunks->ids.size());
    return drawn;
}
