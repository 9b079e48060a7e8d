// Checks the images osgglyphviewer writes, for the viewer tests (tests/viewer/*.cmake, *.sh),
// and those of osgglyphexample (tests/example) and of stock osgviewer (tests/osgdb).
//
//   osgglyphviewer_image_check depth FILE.pfm W H FOV EYE_Z RADIUS X Y Z [X Y Z ...]
//       FILE.pfm is W x H, its corners are +inf (background), and at the pixel where each sphere's
//       centre projects it holds the analytic eye distance to the sphere's front along that
//       pixel's ray (relative error <= 1e-3). The camera is at (0, 0, EYE_Z) looking at the
//       origin with y up and a vertical field of view of FOV degrees; the spheres have RADIUS.
//   osgglyphviewer_image_check differ A.png B.png MIN_FRACTION
//       A and B have the same size and at least MIN_FRACTION of their pixels differ.
//   osgglyphviewer_image_check coverage A.png MIN_FRACTION [MAX_FRACTION]
//       at least MIN_FRACTION (and at most MAX_FRACTION) of the pixels differ from the colour of the
//       bottom-left corner.
//   osgglyphviewer_image_check match A.png BASELINE.png CHANNEL MAX_FRACTION
//       A and BASELINE have the same size and at most MAX_FRACTION of the pixels differ by more
//       than CHANNEL levels (0..255) in a colour channel.
// Prints what it measured; exits 0 when the check holds, 1 when not, 2 on bad arguments.

#include <osgGlyphsHeadless/DepthImage>

#include <osg/Vec3d>
#include <osgDB/ReadFile>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{

/** The eye distance (-z in eye space) where the ray through pixel (px, py) meets a sphere at
 * centre (eye space) and radius, or +inf when it misses. */
double rayDistance(int px, int py, int width, int height, double fovY, const osg::Vec3d& centre,
                   double radius)
{
    const double tanY = std::tan(osg::DegreesToRadians(fovY) / 2.0);
    const double tanX = tanY * width / height;
    // Direction with z = -1: the ray parameter is the eye distance itself.
    const osg::Vec3d d(((px + 0.5) / width * 2.0 - 1.0) * tanX, ((py + 0.5) / height * 2.0 - 1.0) * tanY,
                       -1.0);
    const double b = d * centre;
    const double discriminant = b * b - d.length2() * (centre.length2() - radius * radius);
    if (discriminant < 0.0)
        return INFINITY;
    return (b - std::sqrt(discriminant)) / d.length2();
}

/** The pixel where an eye-space point projects. */
void project(const osg::Vec3d& point, int width, int height, double fovY, int& px, int& py)
{
    const double tanY = std::tan(osg::DegreesToRadians(fovY) / 2.0);
    const double tanX = tanY * width / height;
    px = static_cast<int>(std::floor((point.x() / -point.z() / tanX + 1.0) / 2.0 * width));
    py = static_cast<int>(std::floor((point.y() / -point.z() / tanY + 1.0) / 2.0 * height));
}

int checkDepth(int argc, char** argv)
{
    if (argc < 11 || (argc - 8) % 3 != 0)
        return 2;
    std::string error;
    osg::ref_ptr<osg::Image> depth = osgGlyphsHeadless::readPFM(argv[2], error);
    if (!depth)
    {
        std::cerr << error << std::endl;
        return 1;
    }
    const int width = std::atoi(argv[3]), height = std::atoi(argv[4]);
    const double fov = std::atof(argv[5]), eyeZ = std::atof(argv[6]), radius = std::atof(argv[7]);
    if (depth->s() != width || depth->t() != height)
    {
        std::cerr << argv[2] << ": " << depth->s() << "x" << depth->t() << ", expected " << width << "x"
                  << height << std::endl;
        return 1;
    }
    auto at = [&](int x, int y)
    { return static_cast<double>(*reinterpret_cast<const float*>(depth->data(x, y))); };
    bool ok = true;
    for (int corner = 0; corner < 4; ++corner)
    {
        const int x = corner & 1 ? width - 1 : 0, y = corner & 2 ? height - 1 : 0;
        if (!(std::isinf(at(x, y)) && at(x, y) > 0.0))
        {
            std::cerr << "background pixel (" << x << ", " << y << ") is " << at(x, y) << ", not +inf"
                      << std::endl;
            ok = false;
        }
    }
    for (int arg = 8; arg + 2 < argc; arg += 3)
    {
        const osg::Vec3d centre(std::atof(argv[arg]), std::atof(argv[arg + 1]),
                                std::atof(argv[arg + 2]) - eyeZ);
        int px = 0, py = 0;
        project(centre, width, height, fov, px, py);
        const double expected = rayDistance(px, py, width, height, fov, centre, radius);
        const double actual = at(px, py);
        const double relative = std::fabs(actual - expected) / expected;
        std::cout << "sphere at eye (" << centre.x() << ", " << centre.y() << ", " << centre.z()
                  << "): pixel (" << px << ", " << py << ") depth " << actual << ", analytic " << expected
                  << ", relative error " << relative << std::endl;
        if (!(relative <= 1e-3))
            ok = false;
    }
    return ok ? 0 : 1;
}

osg::ref_ptr<osg::Image> readImage(const char* path)
{
    osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile(path);
    if (!image)
        std::cerr << path << ": cannot read the image" << std::endl;
    return image;
}

/** Whether two pixels differ by more than a few levels in any channel. */
bool differs(const osg::Image& a, int ax, int ay, const osg::Image& b, int bx, int by)
{
    const osg::Vec4 ca = a.getColor(ax, ay), cb = b.getColor(bx, by);
    for (int c = 0; c < 3; ++c)
    {
        if (std::fabs(ca[c] - cb[c]) > 8.0f / 255.0f)
            return true;
    }
    return false;
}

int checkDiffer(int argc, char** argv)
{
    if (argc != 5)
        return 2;
    osg::ref_ptr<osg::Image> a = readImage(argv[2]), b = readImage(argv[3]);
    if (!a || !b)
        return 1;
    if (a->s() != b->s() || a->t() != b->t())
    {
        std::cerr << "the images differ in size" << std::endl;
        return 1;
    }
    int count = 0;
    for (int y = 0; y < a->t(); ++y)
        for (int x = 0; x < a->s(); ++x)
            count += differs(*a, x, y, *b, x, y);
    const double fraction = static_cast<double>(count) / (a->s() * a->t());
    std::cout << "differing pixels: " << fraction << " (at least " << argv[4] << ")" << std::endl;
    return fraction >= std::atof(argv[4]) ? 0 : 1;
}

int checkCoverage(int argc, char** argv)
{
    if (argc != 4 && argc != 5)
        return 2;
    osg::ref_ptr<osg::Image> image = readImage(argv[2]);
    if (!image)
        return 1;
    int count = 0;
    for (int y = 0; y < image->t(); ++y)
        for (int x = 0; x < image->s(); ++x)
            count += differs(*image, x, y, *image, 0, 0);
    const double fraction = static_cast<double>(count) / (image->s() * image->t());
    const double most = argc == 5 ? std::atof(argv[4]) : 1.0;
    std::cout << "pixels unlike the background: " << fraction << " (at least " << argv[3] << ", at most "
              << most << ")" << std::endl;
    return fraction >= std::atof(argv[3]) && fraction <= most ? 0 : 1;
}

int checkMatch(int argc, char** argv)
{
    if (argc != 6)
        return 2;
    osg::ref_ptr<osg::Image> a = readImage(argv[2]), b = readImage(argv[3]);
    if (!a || !b)
        return 1;
    if (a->s() != b->s() || a->t() != b->t())
    {
        std::cerr << argv[2] << " is " << a->s() << "x" << a->t() << ", " << argv[3] << " " << b->s() << "x"
                  << b->t() << std::endl;
        return 1;
    }
    const float tolerance = std::atof(argv[4]) / 255.0f;
    int count = 0;
    float worst = 0.0f;
    for (int y = 0; y < a->t(); ++y)
    {
        for (int x = 0; x < a->s(); ++x)
        {
            const osg::Vec4 ca = a->getColor(x, y), cb = b->getColor(x, y);
            float pixelWorst = 0.0f;
            for (int c = 0; c < 3; ++c)
                pixelWorst = std::max(pixelWorst, std::fabs(ca[c] - cb[c]));
            worst = std::max(worst, pixelWorst);
            count += pixelWorst > tolerance ? 1 : 0;
        }
    }
    const double fraction = static_cast<double>(count) / (a->s() * a->t());
    std::cout << "pixels differing from " << argv[3] << " by more than " << argv[4] << ": " << count << " ("
              << fraction << ", at most " << argv[5] << "); largest difference " << worst * 255.0f
              << std::endl;
    return fraction <= std::atof(argv[5]) ? 0 : 1;
}

}

int main(int argc, char** argv)
{
    const std::string command = argc > 1 ? argv[1] : "";
    const int result = command == "depth"      ? checkDepth(argc, argv)
                       : command == "differ"   ? checkDiffer(argc, argv)
                       : command == "coverage" ? checkCoverage(argc, argv)
                       : command == "match"    ? checkMatch(argc, argv)
                                               : 2;
    if (result == 2)
        std::cerr << "usage: see the comment at the top of tests/viewer/ViewerImageCheck.cpp" << std::endl;
    return result;
}
