#include <osgGlyphsMovie/MovieWriter>

#include <osg/Notify>

extern "C"
{
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <vector>

using namespace osgGlyphsMovie;

namespace
{

struct FormatContextDeleter
{
    void operator()(AVFormatContext* context) const
    {
        if (!(context->oformat->flags & AVFMT_NOFILE))
            avio_closep(&context->pb);
        avformat_free_context(context);
    }
};

struct CodecContextDeleter
{
    void operator()(AVCodecContext* context) const { avcodec_free_context(&context); }
};

struct FrameDeleter
{
    void operator()(AVFrame* frame) const { av_frame_free(&frame); }
};

struct PacketDeleter
{
    void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};

struct ScalerDeleter
{
    void operator()(SwsContext* scaler) const { sws_freeContext(scaler); }
};

/** av_err2str, which C++ cannot compile (it takes a compound literal's address). */
std::string avError(int code)
{
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof(text));
    return text;
}

std::string sizeText(int width, int height)
{
    return std::to_string(width) + "x" + std::to_string(height);
}

/** libav logs its progress and warnings to stderr at AV_LOG_INFO, its default: keep only errors,
 * unless the application chose a level of its own. */
void quietLibav()
{
    static std::once_flag once;
    std::call_once(once,
                   []
                   {
                       if (av_log_get_level() == AV_LOG_INFO)
                           av_log_set_level(AV_LOG_ERROR);
                   });
}

std::string extensionOf(const std::string& path)
{
    const std::string::size_type dot = path.find_last_of('.');
    const std::string::size_type slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return std::string();
    return path.substr(dot);
}

bool isH264Container(const AVOutputFormat* format)
{
    for (const char* name : {"mp4", "mov", "matroska"})
    {
        if (std::strcmp(format->name, name) == 0)
            return true;
    }
    return format->video_codec == AV_CODEC_ID_H264;
}

/** libx264 where the container holds H.264 well (never a hardware encoder by chance), else the
 * container's own default; MPEG-4 part 2 when that has no encoder. */
const AVCodec* defaultEncoder(const AVOutputFormat* format, AVCodecID guessed)
{
    if (isH264Container(format))
    {
        if (const AVCodec* x264 = avcodec_find_encoder_by_name("libx264"))
            return x264;
        return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
    }
    const AVCodec* codec = avcodec_find_encoder(guessed);
    return codec ? codec : avcodec_find_encoder(AV_CODEC_ID_MPEG4);
}

/** An encoder by its own name ("libx264") or by its codec's ("h264"). */
const AVCodec* namedEncoder(const std::string& name)
{
    if (const AVCodec* codec = avcodec_find_encoder_by_name(name.c_str()))
        return codec;
    if (const AVCodecDescriptor* descriptor = avcodec_descriptor_get_by_name(name.c_str()))
        return avcodec_find_encoder(descriptor->id);
    return nullptr;
}

bool encoderTakes(const AVCodec* codec, AVPixelFormat format)
{
    if (!codec->pix_fmts)
        return true;
    for (const AVPixelFormat* candidate = codec->pix_fmts; *candidate != AV_PIX_FMT_NONE; ++candidate)
    {
        if (*candidate == format)
            return true;
    }
    return false;
}

std::string formatsTaken(const AVCodec* codec)
{
    std::string names;
    for (const AVPixelFormat* candidate = codec->pix_fmts; candidate && *candidate != AV_PIX_FMT_NONE;
         ++candidate)
        names += (names.empty() ? "" : ", ") + std::string(av_get_pix_fmt_name(*candidate));
    return names;
}

/** The pixel format to encode, or AV_PIX_FMT_NONE with the reason. */
AVPixelFormat choosePixelFormat(const AVCodec* codec, const std::string& requested, std::string& reason)
{
    if (requested.empty())
    {
        if (encoderTakes(codec, AV_PIX_FMT_YUV420P))
            return AV_PIX_FMT_YUV420P;
        return avcodec_find_best_pix_fmt_of_list(codec->pix_fmts, AV_PIX_FMT_RGBA, 0, nullptr);
    }
    const AVPixelFormat format = av_get_pix_fmt(requested.c_str());
    if (format == AV_PIX_FMT_NONE)
        reason = "libavutil knows no pixel format \"" + requested + "\"";
    else if (!encoderTakes(codec, format))
        reason = std::string(codec->name) + " cannot encode " + requested + " (it takes " +
                 formatsTaken(codec) + ")";
    return reason.empty() ? format : AV_PIX_FMT_NONE;
}

bool isFullRange(AVPixelFormat format)
{
    return std::strncmp(av_get_pix_fmt_name(format), "yuvj", 4) == 0;
}

bool isRGB(AVPixelFormat format)
{
    return (av_pix_fmt_desc_get(format)->flags & AV_PIX_FMT_FLAG_RGB) != 0;
}

/** Rendered frames are sRGB, whose primaries are BT.709's. The matrix from RGB to YUV is the one
 * players assume for the size where neither the codec nor the container tags it (MPEG-4 part 2 in
 * AVI): BT.601 up to standard definition, BT.709 from width 1280 or height 577 up. */
void tagColours(AVCodecContext* context)
{
    if (isRGB(context->pix_fmt))
        return;
    const bool highDefinition = context->width >= 1280 || context->height > 576;
    context->colorspace = highDefinition ? AVCOL_SPC_BT709 : AVCOL_SPC_SMPTE170M;
    context->color_primaries = AVCOL_PRI_BT709;
    context->color_trc = AVCOL_TRC_BT709;
    context->color_range = isFullRange(context->pix_fmt) ? AVCOL_RANGE_JPEG : AVCOL_RANGE_MPEG;
}

int swscaleMatrix(const AVCodecContext* context)
{
    return context->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_ITU601;
}

/** The CRF of encoders that have one, else a fixed quantiser (see MovieOptions::quality). */
bool setQuality(AVCodecContext* context, int quality, std::string& reason)
{
    if (quality < 0)
    {
        reason = "the quality " + std::to_string(quality) + " is negative: 0 is the best";
        return false;
    }
    const AVOption* crf =
        context->priv_data ? av_opt_find(context->priv_data, "crf", nullptr, 0, 0) : nullptr;
    if (crf)
    {
        if (quality > crf->max)
        {
            reason = "the quality " + std::to_string(quality) + " is past " + context->codec->name +
                     "'s largest crf, " + std::to_string(static_cast<int>(crf->max));
            return false;
        }
        context->bit_rate = 0; // constant quality, no bit-rate target
        av_opt_set_int(context->priv_data, "crf", quality, 0);
        return true;
    }
    const double quantiser = std::clamp(2.0 * std::pow(2.0, (quality - 18) / 6.0), 1.0, 31.0);
    context->flags |= AV_CODEC_FLAG_QSCALE;
    context->global_quality = static_cast<int>(std::lround(FF_QP2LAMBDA * quantiser));
    return true;
}

/** The frame rate as a fraction for the time base, or 0/1 when none is close enough. */
AVRational frameRate(double framesPerSecond)
{
    if (!std::isfinite(framesPerSecond) || framesPerSecond <= 0.0)
        return AVRational{0, 1};
    const AVRational rate = av_d2q(framesPerSecond, 65535); // MPEG-4 part 2's largest time base
    if (rate.num <= 0 || std::abs(av_q2d(rate) - framesPerSecond) > 1e-4 * framesPerSecond)
        return AVRational{0, 1};
    return rate;
}

AVPixelFormat sourceFormat(const osg::Image& image)
{
    if (image.getDataType() != GL_UNSIGNED_BYTE)
        return AV_PIX_FMT_NONE;
    switch (image.getPixelFormat())
    {
    case GL_RGBA:
        return AV_PIX_FMT_RGBA;
    case GL_RGB:
        return AV_PIX_FMT_RGB24;
    case GL_BGRA:
        return AV_PIX_FMT_BGRA;
    case GL_BGR:
        return AV_PIX_FMT_BGR24;
    default:
        return AV_PIX_FMT_NONE;
    }
}

int padded(int size, int log2Alignment)
{
    const int alignment = 1 << log2Alignment;
    return (size + alignment - 1) / alignment * alignment;
}

}

struct MovieWriter::Encoder
{
    std::unique_ptr<AVFormatContext, FormatContextDeleter> format;
    std::unique_ptr<AVCodecContext, CodecContextDeleter> codec;
    AVStream* stream = nullptr; // owned by format
    std::unique_ptr<AVFrame, FrameDeleter> frame;
    std::unique_ptr<AVPacket, PacketDeleter> packet;
    std::unique_ptr<SwsContext, ScalerDeleter> scaler;
    /** The frame top row first, padded to the encoded size, in the image's own RGB layout. */
    std::vector<unsigned char> staging;

    // Each leaves the reason when it fails.
    /** The container for path's extension; the encoder named (empty: the container's default). */
    const AVCodec* createContainer(const std::string& path, const std::string& name, std::string& reason);
    bool openCodec(const AVCodec* encoder, AVPixelFormat pixelFormat, int width, int height, AVRational rate,
                   int quality, std::string& reason);
    /** The stream, from the open codec, and the frame and packet passed through it. */
    bool createStream(std::string& reason);
};

const AVCodec* MovieWriter::Encoder::createContainer(const std::string& path, const std::string& name,
                                                     std::string& reason)
{
    AVFormatContext* context = nullptr;
    avformat_alloc_output_context2(&context, nullptr, nullptr, path.c_str());
    format.reset(context);
    if (!context)
    {
        reason = "libavformat knows no container for the extension \"" + extensionOf(path) + "\"";
        return nullptr;
    }
    const AVOutputFormat* container = context->oformat;
    const AVCodecID guessed = av_guess_codec(container, nullptr, path.c_str(), nullptr, AVMEDIA_TYPE_VIDEO);
    const AVCodec* encoder = nullptr;
    if (guessed == AV_CODEC_ID_NONE)
        reason = std::string("the ") + container->name + " container holds no video";
    else if (!(encoder = name.empty() ? defaultEncoder(container, guessed) : namedEncoder(name)) ||
             encoder->type != AVMEDIA_TYPE_VIDEO)
        reason =
            "libavcodec has no video encoder \"" + (name.empty() ? avcodec_get_name(guessed) : name) + "\"";
    else if (avformat_query_codec(container, encoder->id, FF_COMPLIANCE_NORMAL) == 0)
        reason =
            std::string("the ") + container->name + " container cannot hold " + avcodec_get_name(encoder->id);
    return reason.empty() ? encoder : nullptr;
}

bool MovieWriter::Encoder::openCodec(const AVCodec* encoder, AVPixelFormat pixelFormat, int width, int height,
                                     AVRational rate, int quality, std::string& reason)
{
    codec.reset(avcodec_alloc_context3(encoder));
    if (!codec)
    {
        reason = "out of memory for the encoder";
        return false;
    }
    AVCodecContext* context = codec.get();
    context->width = width;
    context->height = height;
    context->pix_fmt = pixelFormat;
    context->time_base = av_inv_q(rate);
    context->framerate = rate;
    context->sample_aspect_ratio = AVRational{1, 1};
    tagColours(context);
    if (format->oformat->flags & AVFMT_GLOBALHEADER)
        context->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (!setQuality(context, quality, reason))
        return false;
    const int opened = avcodec_open2(context, encoder, nullptr);
    if (opened < 0)
        reason = std::string("cannot open the encoder ") + encoder->name + ": " + avError(opened);
    return opened >= 0;
}

bool MovieWriter::Encoder::createStream(std::string& reason)
{
    stream = avformat_new_stream(format.get(), nullptr);
    frame.reset(av_frame_alloc());
    packet.reset(av_packet_alloc());
    if (!stream || !frame || !packet || avcodec_parameters_from_context(stream->codecpar, codec.get()) < 0)
    {
        reason = "out of memory for the stream";
        return false;
    }
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    frame->format = codec->pix_fmt;
    frame->width = codec->width;
    frame->height = codec->height;
    const int allocated = av_frame_get_buffer(frame.get(), 0);
    if (allocated < 0)
        reason = "cannot allocate the frame: " + avError(allocated);
    return allocated >= 0;
}

MovieWriter::MovieWriter() = default;

MovieWriter::~MovieWriter()
{
    std::string error;
    if (!close(error))
        OSG_WARN << "osgGlyphsMovie: " << error << std::endl;
}

bool MovieWriter::fail(const std::string& reason, std::string& error) const
{
    error = _path + ": " + reason;
    return false;
}

bool MovieWriter::open(const std::string& path, int width, int height, const MovieOptions& options,
                       std::string& error)
{
    if (_encoder)
        return fail("a movie is open: close it before opening " + path, error);
    quietLibav();
    _path = path;
    _width = _encodedWidth = width;
    _height = _encodedHeight = height;
    _codecName.clear();
    _encoderName.clear();
    _pixelFormat.clear();
    _framesWritten = 0;
    if (width <= 0 || height <= 0)
        return fail("the size " + sizeText(width, height) + " has no pixels", error);

    _encoder = std::make_unique<Encoder>();
    if (!createEncoder(options, error) || !startFile(error))
    {
        _encoder.reset();
        return false;
    }
    return true;
}

bool MovieWriter::createEncoder(const MovieOptions& options, std::string& error)
{
    Encoder& encoder = *_encoder;
    const AVRational rate = frameRate(options.framesPerSecond);
    std::string reason;
    if (rate.num == 0)
        reason = "the frame rate " + std::to_string(options.framesPerSecond) +
                 " is no positive fraction of terms up to 65535";
    const AVCodec* codec = reason.empty() ? encoder.createContainer(_path, options.codec, reason) : nullptr;
    const AVPixelFormat pixelFormat =
        codec ? choosePixelFormat(codec, options.pixelFormat, reason) : AV_PIX_FMT_NONE;
    if (pixelFormat == AV_PIX_FMT_NONE)
        return fail(reason.empty() ? std::string(codec->name) + " takes no RGB input" : reason, error);

    const AVPixFmtDescriptor* descriptor = av_pix_fmt_desc_get(pixelFormat);
    _encodedWidth = padded(_width, descriptor->log2_chroma_w);
    _encodedHeight = padded(_height, descriptor->log2_chroma_h);
    if (_encodedWidth != _width || _encodedHeight != _height)
        OSG_NOTICE << "osgGlyphsMovie: " << _path << ": " << sizeText(_width, _height) << " is padded to "
                   << sizeText(_encodedWidth, _encodedHeight) << " for " << descriptor->name
                   << ", repeating the last column and row" << std::endl;

    if (!encoder.openCodec(codec, pixelFormat, _encodedWidth, _encodedHeight, rate, options.quality,
                           reason) ||
        !encoder.createStream(reason))
        return fail(reason, error);
    _codecName = avcodec_get_name(codec->id);
    _encoderName = codec->name;
    _pixelFormat = descriptor->name;
    return true;
}

bool MovieWriter::startFile(std::string& error)
{
    AVFormatContext* format = _encoder->format.get();
    const bool ownsFile = !(format->oformat->flags & AVFMT_NOFILE);
    if (ownsFile)
    {
        const int created = avio_open(&format->pb, _path.c_str(), AVIO_FLAG_WRITE);
        if (created < 0)
            return fail("cannot create the file: " + avError(created), error);
    }
    const int written = avformat_write_header(format, nullptr);
    if (written >= 0)
        return true;
    _encoder.reset();
    if (ownsFile)
        std::remove(_path.c_str());
    return fail("cannot write the header: " + avError(written), error);
}

bool MovieWriter::writeFrame(const osg::Image& image, std::string& error)
{
    if (!_encoder)
    {
        error = (_path.empty() ? std::string("osgGlyphsMovie::MovieWriter") : _path) + ": no movie is open";
        return false;
    }
    if (!checkImage(image, error))
        return false;
    stageImage(image);
    if (!convertStaged(image, error) || !encode(false, error))
        return false;
    ++_framesWritten;
    return true;
}

bool MovieWriter::checkImage(const osg::Image& image, std::string& error) const
{
    const std::string frame = "frame " + std::to_string(_framesWritten);
    if (image.s() != _width || image.t() != _height || image.r() != 1)
        return fail(frame + " is " + sizeText(image.s(), image.t()) +
                        (image.r() != 1 ? "x" + std::to_string(image.r()) : std::string()) +
                        ", the movie was opened at " + sizeText(_width, _height),
                    error);
    if (!image.data())
        return fail(frame + " has no pixels", error);
    if (sourceFormat(image) == AV_PIX_FMT_NONE)
    {
        char formats[64];
        std::snprintf(formats, sizeof(formats), "pixel format 0x%x, data type 0x%x", image.getPixelFormat(),
                      image.getDataType());
        return fail(frame + " is not 8-bit RGBA, RGB, BGRA or BGR (" + formats + ")", error);
    }
    return true;
}

void MovieWriter::stageImage(const osg::Image& image)
{
    const std::size_t pixel = image.getPixelSizeInBits() / 8;
    const std::size_t rowBytes = pixel * _width;
    const std::size_t stride = pixel * _encodedWidth;
    std::vector<unsigned char>& staging = _encoder->staging;
    staging.resize(stride * _encodedHeight);
    const bool bottomUp = image.getOrigin() == osg::Image::BOTTOM_LEFT;
    for (int y = 0; y < _encodedHeight; ++y)
    {
        const int pictureRow = std::min(y, _height - 1);
        unsigned char* target = staging.data() + y * stride;
        std::memcpy(target, image.data(0, bottomUp ? _height - 1 - pictureRow : pictureRow), rowBytes);
        for (int x = _width; x < _encodedWidth; ++x)
            std::memcpy(target + x * pixel, target + (x - 1) * pixel, pixel);
    }
}

bool MovieWriter::convertStaged(const osg::Image& image, std::string& error)
{
    Encoder& encoder = *_encoder;
    const AVPixelFormat source = sourceFormat(image);
    const AVPixelFormat target = encoder.codec->pix_fmt;
    encoder.scaler.reset(sws_getCachedContext(encoder.scaler.release(), _encodedWidth, _encodedHeight, source,
                                              _encodedWidth, _encodedHeight, target, SWS_BICUBIC, nullptr,
                                              nullptr, nullptr));
    if (!encoder.scaler)
        return fail(std::string("libswscale cannot convert ") + av_get_pix_fmt_name(source) + " to " +
                        av_get_pix_fmt_name(target),
                    error);
    if (!isRGB(target))
    {
        const int* matrix = sws_getCoefficients(swscaleMatrix(encoder.codec.get()));
        sws_setColorspaceDetails(encoder.scaler.get(), matrix, 1, matrix, isFullRange(target) ? 1 : 0, 0,
                                 1 << 16, 1 << 16);
    }
    const int writable = av_frame_make_writable(encoder.frame.get());
    if (writable < 0)
        return fail("cannot reuse the frame: " + avError(writable), error);

    const uint8_t* planes[1] = {encoder.staging.data()};
    const int strides[1] = {static_cast<int>(encoder.staging.size() / _encodedHeight)};
    sws_scale(encoder.scaler.get(), planes, strides, 0, _encodedHeight, encoder.frame->data,
              encoder.frame->linesize);
    encoder.frame->pts = _framesWritten;
    // Encoders with a fixed quantiser (AV_CODEC_FLAG_QSCALE) take it from each frame.
    encoder.frame->quality = encoder.codec->global_quality;
    return true;
}

bool MovieWriter::encode(bool flush, std::string& error)
{
    Encoder& encoder = *_encoder;
    int result = avcodec_send_frame(encoder.codec.get(), flush ? nullptr : encoder.frame.get());
    while (result >= 0)
    {
        result = avcodec_receive_packet(encoder.codec.get(), encoder.packet.get());
        if (result == AVERROR(EAGAIN) || result == AVERROR_EOF)
            return true;
        if (result < 0)
            break;
        av_packet_rescale_ts(encoder.packet.get(), encoder.codec->time_base, encoder.stream->time_base);
        encoder.packet->stream_index = encoder.stream->index;
        // The muxer takes the packet's reference, on failure too.
        result = av_interleaved_write_frame(encoder.format.get(), encoder.packet.get());
        if (result < 0)
            return fail("cannot write frame " + std::to_string(_framesWritten) + ": " + avError(result),
                        error);
    }
    return fail("cannot encode frame " + std::to_string(_framesWritten) + ": " + avError(result), error);
}

bool MovieWriter::close(std::string& error)
{
    if (!_encoder)
        return true;
    std::string firstError;
    bool closed = encode(true, firstError);
    AVFormatContext* format = _encoder->format.get();
    const int trailer = av_write_trailer(format);
    if (trailer < 0 && closed)
        closed = fail("cannot write the trailer: " + avError(trailer), firstError);
    if (!(format->oformat->flags & AVFMT_NOFILE))
    {
        const int flushed = avio_closep(&format->pb);
        if (flushed < 0 && closed)
            closed = fail("cannot close the file: " + avError(flushed), firstError);
    }
    _encoder.reset();
    if (!closed)
        error = firstError;
    return closed;
}
