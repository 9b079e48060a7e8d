#include <osgGlyphsTiles/TileRoot>

#include <osg/NodeVisitor>
#include <osg/PagedLOD>
#include <osgDB/Registry>
#include <osgUtil/CullVisitor>

using namespace osgGlyphsTiles;

const char* const osgGlyphsTiles::GLYPH_BUDGET_OPTION = "glyphBudget";

namespace
{

class DatabaseOptionsSetter : public osg::NodeVisitor
{
public:
    explicit DatabaseOptionsSetter(osgDB::Options* options)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), _options(options)
    {
    }

    void apply(osg::PagedLOD& lod) override
    {
        if (!lod.getDatabaseOptions())
            lod.setDatabaseOptions(_options);
        traverse(lod);
    }

private:
    osgDB::Options* _options;
};

/** Computes the bound of every node it visits that the last change left dirty. */
class BoundComputer : public osg::NodeVisitor
{
public:
    BoundComputer() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}

    void apply(osg::Node& node) override
    {
        node.getBound();
        traverse(node);
    }
};

}

void osgGlyphsTiles::setTileDatabaseOptions(osg::Node& node, osgDB::Options* options)
{
    DatabaseOptionsSetter setter(options);
    node.accept(setter);
}

TileRoot::TileRoot() : _budget(new TileBudget), _checking(new TileCheckingReadCallback)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
    const osgDB::Options* registryOptions = osgDB::Registry::instance()->getOptions();
    _databaseOptions = registryOptions ? registryOptions->cloneOptions() : new osgDB::Options;
    _databaseOptions->setReadFileCallback(_checking.get());
}

TileRoot::TileRoot(const TileRoot& other, const osg::CopyOp& copyop)
    : osg::Group(other, copyop), _budget(new TileBudget(other.getGlyphBudget())), _checking(other._checking),
      _databaseOptions(other._databaseOptions)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

void TileRoot::setGlyphBudget(std::size_t maxGlyphs)
{
    _budget->setMaxGlyphs(maxGlyphs);
}

std::size_t TileRoot::getGlyphBudget() const
{
    return _budget->getMaxGlyphs();
}

bool TileRoot::insertChild(unsigned int index, osg::Node* child)
{
    if (child)
        setTileDatabaseOptions(*child, _databaseOptions.get());
    return osg::Group::insertChild(index, child);
}

bool TileRoot::addChild(osg::Node* child)
{
    return TileRoot::insertChild(getNumChildren(), child);
}

bool TileRoot::setChild(unsigned int index, osg::Node* child)
{
    if (child)
        setTileDatabaseOptions(*child, _databaseOptions.get());
    return osg::Group::setChild(index, child);
}

void TileRoot::traverse(osg::NodeVisitor& nv)
{
    if (nv.getVisitorType() == osg::NodeVisitor::UPDATE_VISITOR)
    {
        // The DatabasePager merged and expired tiles just before: their parents' bounds are dirty,
        // and the PagedLODs' user-defined centres keep getBound() from reaching below them. Cull
        // threads of several cameras would compute them together.
        BoundComputer bounds;
        osg::Group::traverse(bounds);
        getBound();
    }
    osgUtil::CullVisitor* cv = nv.asCullVisitor();
    if (!cv || getGlyphBudget() == 0)
    {
        osg::Group::traverse(nv);
        return;
    }
    const float baseScale = cv->getLODScale();
    cv->setLODScale(static_cast<float>(baseScale * _budget->computeLODScale(*this, *cv)));
    osg::Group::traverse(nv);
    cv->setLODScale(baseScale);
}
