/* osgGlyphs - private: the program of a technique, which reports its own failure to compile or
 * link. Not installed. */

#ifndef OSGGLYPHS_GLYPHPROGRAM_H
#define OSGGLYPHS_GLYPHPROGRAM_H 1

#include <osgGlyphs/GlyphTechnique>

#include <osg/Program>

#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace osgGlyphs
{
namespace detail
{

/** What begins the osg::notify message of a program error: "osgGlyphs: glyph program '". */
extern const char* const PROGRAM_ERROR_NOTIFY_PREFIX;

/** The osg::Program of a technique: its shader files, expanded with their includes, for every
 * variant that OSG define lists select.
 *
 * When a variant first fails to compile or link in a context, apply() (the draw thread, with the
 * context current) hands one line to the error function: "glyph program 'osgGlyphs
 * geometry-shader' does not compile: /data/osgGlyphs/sphere.glsl:12: error: ...", the file and
 * line of the first error of GL's info log. */
class GlyphProgram : public osg::Program
{
public:
    typedef std::function<void(const std::string&)> ErrorFunction;

    GlyphProgram() = default;
    GlyphProgram(const GlyphTechnique& technique, const std::map<std::string, std::string>& generated,
                 const ErrorFunction& onError);
    /** A program of these shader files, named "osgGlyphs <name>". */
    GlyphProgram(const std::string& name, const std::vector<GlyphShaderFile>& files,
                 const std::map<std::string, std::string>& generated, const ErrorFunction& onError);
    GlyphProgram(const GlyphProgram& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_StateAttribute(osgGlyphs, GlyphProgram, PROGRAM);

    /** Re-reads every shader file; the shaders recompile, and fail anew, on the next frame. */
    void reloadShaders();

    void apply(osg::State& state) const override;

protected:
    ~GlyphProgram() override = default;

    /** The line that says why the program of the current variant failed. */
    std::string describeFailure(osg::State& state, const PerContextProgram& program) const;

    std::map<std::string, std::string> _generated;
    ErrorFunction _onError;

    mutable std::mutex _mutex;
    /** The files of each shader's source, by GLSL source string number. */
    std::map<const osg::Shader*, std::vector<std::string>> _files;
    /** The programs of variants and contexts whose failure was reported. */
    mutable std::set<const PerContextProgram*> _reported;
};

}
}

#endif
