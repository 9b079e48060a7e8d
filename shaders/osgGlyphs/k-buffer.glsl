// osgGlyphs: the k-buffer of osgGlyphs::DepthPeeling (method K_BUFFER). In one pass, every
// fragment of the transparent children is inserted into its pixel's list of the nearest fragments
// so far, sorted by depth; a full-screen pass then blends each list over the picture and empties
// it. The list is exactly what the same number of peeled layers would hold.
//
// It needs GL_ARB_shader_storage_buffer_object, GL_ARB_shading_language_420pack,
// GL_ARB_shading_language_packing and GL_ARB_shader_image_load_store (the buffer's coherent
// qualifier and, to insert, the memory barrier), all in OpenGL 4.3, which a shader enables at its
// top: the directives may not follow code.

// Per pixel (row by row from the window's origin): a lock (0 free, 1 held), the depths of the
// nearest fragments as float bits (nearest first, EMPTY_LAYER where none), and their colours as
// 8-bit RGBA, not premultiplied.
layout(std430, binding = 0) coherent buffer osgGlyphs_KBufferBlock
{
    uint osgGlyphs_kBuffer[];
};

// x: the pixels of a row, y: the layers kept per pixel.
uniform ivec2 osgGlyphs_kBufferSize;

const uint EMPTY_LAYER = 0xffffffffu;

uint kBufferLock(ivec2 pixel)
{
    return uint(pixel.y * osgGlyphs_kBufferSize.x + pixel.x) * uint(1 + 2 * osgGlyphs_kBufferSize.y);
}

uint kBufferDepthSlot(ivec2 pixel, int layer)
{
    return kBufferLock(pixel) + 1u + uint(layer);
}

uint kBufferColorSlot(ivec2 pixel, int layer)
{
    return kBufferDepthSlot(pixel, layer) + uint(osgGlyphs_kBufferSize.y);
}
