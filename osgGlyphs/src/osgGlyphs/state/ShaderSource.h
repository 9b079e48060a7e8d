/* osgGlyphs - private: shader sources with their includes expanded, and the files they came
 * from. Not installed. */

#ifndef OSGGLYPHS_SHADERSOURCE_H
#define OSGGLYPHS_SHADERSOURCE_H 1

#include <map>
#include <string>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** A shader's source with every `#include "file"` replaced by that file (each once), and the
 * files it was made of, the shader's own first. #line directives number each file's lines as in
 * the file, with the file's index in files as GLSL source string number, so that an info log's
 * "2:14(3): error: ..." means line 14 of files[2]. */
struct ExpandedShaderSource
{
    std::string text;
    /** The file read (on OSG's data path or installed), or the name for an embedded or
     * generated source. */
    std::vector<std::string> files;
};

/** The expanded source of a shader file under OSG's data path ("osgGlyphs/impostor.frag");
 * generated files may be passed in (name and text). Problems are reported through osg::notify. */
ExpandedShaderSource expandShaderSource(const std::string& name,
                                        const std::map<std::string, std::string>& generated);

}
}

#endif
