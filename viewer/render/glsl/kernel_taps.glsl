// The taps a filter reads (filter_taps, lookup/kernel_taps.cpp: the CPU's lists, which the pass
// packs as (offset, weight)), and the Poisson disk's turn by pixel_rotation of the fragment's pixel.
uniform int shadowTapCount;
uniform vec3 shadowTaps[shadowMaxTaps];  // (offset in the kernel's radius, weight)
uniform int shadowTapsTurn;              // pcf's Poisson disk turns per pixel
uniform ivec2 shadowImageOrigin;  // the renderer's corner in the window, and its height: the image's pixels
uniform int shadowImageHeight;
// pixel_rotation of the fragment's pixel, counted as the CPU's images count them: row 0 at the top.
float shadowPixelRotation() {
  ivec2 pixel = ivec2(floor(gl_FragCoord.xy)) - shadowImageOrigin;
  pixel.y = shadowImageHeight - 1 - pixel.y;
  return 6.283185307179586 * (float(shadowHashPixel(uint(pixel.x), uint(pixel.y))) / 4294967296.0);
}
vec2 shadowRotated(vec2 v, float c, float s) { return vec2(c * v.x - s * v.y, s * v.x + c * v.y); }
