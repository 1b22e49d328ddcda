// What ray-gen writes, a value per pixel, goes to storage buffers rather than images: lavapipe
// stores to an image one lane at a time (0.6-0.7 ms of the trace a store at 320x180, against
// 0.1-0.2 ms for a buffer's). Pixel (x, y) is element pixelIndex of each, whatever the picture's
// size this frame. Included after the frame's uniforms (FrameBlock).
int pixelIndex(ivec2 pixel) { return pixel.y * int(frame.pixelBuffers.x) + pixel.x; }
