#pragma once
// Doubles a picture's width and height on the CPU with bilinear weights, as a linear sampler
// stretching it over twice its size would: each output pixel takes 3/4 of the nearest input
// pixel and 1/4 of the next one along each axis, clamped at the edges. The play window uses it
// on CPU drivers, where llvmpipe's fragment pass over the window's pixels cost more than the
// whole scaling does here (docs/PERFORMANCE.md, session 38).
#include <cstddef>
#include <cstdint>
#include <span>

namespace render {

// `source`: `width` x `height` RGBA8 pixels, rows packed. `target`: 2*width x 2*height pixels
// of 4 bytes, `targetRowBytes` apart; each gets the source's channels rounded to the nearest
// byte, red and blue swapped when `swapRedBlue` (a B8G8R8A8 window), alpha 255 (the window is
// opaque).
void doublePicture(const uint8_t* source, uint32_t width, uint32_t height, uint8_t* target,
                   size_t targetRowBytes, bool swapRedBlue);

// How many 16-bit values of scratch space doublePictureRows needs for a picture `width` wide.
size_t doublingScratchSize(uint32_t width);

// doublePicture's output rows 2 * firstRow to 2 * endRow (exclusive) only, at their places in
// `target`, working in `scratch` (at least doublingScratchSize(width) values); it allocates
// nothing and throws nothing. Bands of one picture can be doubled on different threads, each
// with scratch space of its own.
void doublePictureRows(const uint8_t* source, uint32_t width, uint32_t height, uint32_t firstRow,
                       uint32_t endRow, uint8_t* target, size_t targetRowBytes, bool swapRedBlue,
                       std::span<uint16_t> scratch);

// The same pixels one for one (no scaling): channel order and alpha as doublePicture's.
void copyPicture(const uint8_t* source, uint32_t width, uint32_t height, uint8_t* target,
                 size_t targetRowBytes, bool swapRedBlue);

}  // namespace render
