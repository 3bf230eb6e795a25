// hash_pixel: Wellons' lowbias32; GLSL's uint arithmetic wraps as C++'s does.
uint shadowHashPixel(uint x, uint y) {
  uint h = x * 1664525u ^ y * 22695477u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}
