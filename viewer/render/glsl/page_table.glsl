// Stage 2 under MapSelection::Rule::pages (a virtual map's resident pages): resident_map,
// page_holding and page_world_to_uvz (maps/page_table.cpp) line by line. A setup of pages holds far
// more maps than the uniform arrays, so this program declares the per-map arrays the lookup reads
// (shadowMapWorldToUvz, shadowMapViewport, shadowMapTileTexels) as plain variables, and
// shadowSelectPage loads the selected page into entry 0 of them: from its level's matrix and its
// place in the level, and its slot of the pool. Every function after it then reads map 0 as the
// other rules read theirs.
uniform int shadowPageLevelCount;
uniform mat4 shadowPageLevelWorldToUvz[shadowMaxPageLevels];  // each level's whole virtual map, w = 1
uniform int shadowPagesPerSide;
// PageTable::resident: texel (x, level * pages_per_side + y) holds the map of page (x, y) of the
// level, -1 where it is not resident.
uniform isampler2D shadowPageTable;
// Each map's slot of the pool: texel (map, 0) its viewport (u0, v0, u1, v1), (map, 1) its first and
// last texel (x, y, x, y), rounded on the CPU as the other rules' tiles are.
uniform sampler2D shadowPageSlots;
// page_holding: the page of `level` that holds p (its (u, v) in [0,1]², the far edge in the last
// page); (-1, -1) outside the level.
ivec2 shadowPageHolding(int level, vec3 p) {
  vec4 uvz = shadowPageLevelWorldToUvz[level] * vec4(p, 1.0);  // w = 1: orthographic
  if (!(uvz.x >= 0.0 && uvz.x <= 1.0 && uvz.y >= 0.0 && uvz.y <= 1.0)) return ivec2(-1);
  int last = shadowPagesPerSide - 1;
  return min(ivec2(uvz.xy * float(shadowPagesPerSide)), ivec2(last));
}
// resident_map: the finest resident page that holds p, and the map holding it; -1 for none.
int shadowResidentMap(vec3 p, out int level, out ivec2 page) {
  for (level = 0; level < shadowPageLevelCount; ++level) {
    page = shadowPageHolding(level, p);
    if (page.x < 0) continue;  // beyond this level: a coarser one may hold it
    int map = texelFetch(shadowPageTable, ivec2(page.x, level * shadowPagesPerSide + page.y), 0).r;
    if (map >= 0) return map;
  }
  return -1;
}
// page_world_to_uvz: the level's map with its (u, v) square cut to the page's, u' = u n - x,
// v' = v n - y (n pages per side); d unchanged.
mat4 shadowPageWorldToUvz(int level, ivec2 page) {
  float n = float(shadowPagesPerSide);
  mat4 pageFromLevel = mat4(1.0);
  pageFromLevel[0][0] = n;
  pageFromLevel[1][1] = n;
  pageFromLevel[3] = vec4(-vec2(page), 0.0, 1.0);
  return pageFromLevel * shadowPageLevelWorldToUvz[level];
}
// The selected page's level (the cascade overlay's colour under pages: kMapPalette[level % 8]) and
// its place in the level (where its filter's taps reach their neighbours).
int shadowSelectedLevel = 0;
ivec2 shadowSelectedPage = ivec2(0);
// select_map under Rule::pages: the resident page holding p loaded as map 0; -1 for none (lit).
int shadowSelectPage(vec3 p) {
  int level;
  ivec2 page;
  int map = shadowResidentMap(p, level, page);
  if (map < 0) return -1;
  shadowSelectedLevel = level;
  shadowSelectedPage = page;
  shadowMapWorldToUvz[0] = shadowPageWorldToUvz(level, page);
  shadowMapViewport[0] = texelFetch(shadowPageSlots, ivec2(map, 0), 0);
  shadowMapTileTexels[0] = texelFetch(shadowPageSlots, ivec2(map, 1), 0);
  return 0;
}
// ShadowReader::tap_texel under pages: a tap of the selected page (map 0) beyond its square reads
// the resident page of its level there (page_across, maps/page_table.cpp), else map 0's texel kept
// in its tile; the texel, and its centre in map 0's (u, v) (texel_centre_uv, plus the offset).
ivec2 shadowPageTapTexel(vec2 uv, out vec2 centreUv) {
  vec4 tile = shadowMapViewport[0], texels = shadowMapTileTexels[0];
  ivec2 offset = ivec2(0);
  bool inside = uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y < 1.0;
  ivec2 there = shadowSelectedPage + ivec2(floor(uv));
  if (!inside && all(greaterThanEqual(there, ivec2(0))) && all(lessThan(there, ivec2(shadowPagesPerSide)))) {
    int map = texelFetch(shadowPageTable, ivec2(there.x, shadowSelectedLevel * shadowPagesPerSide + there.y), 0).r;
    if (map >= 0) {
      offset = ivec2(floor(uv));
      tile = texelFetch(shadowPageSlots, ivec2(map, 0), 0);
      texels = texelFetch(shadowPageSlots, ivec2(map, 1), 0);
    }
  }
  vec2 local = uv - vec2(offset);
  vec2 t = (tile.xy + local * (tile.zw - tile.xy)) * float(shadowResolution);
  ivec2 texel = ivec2(clamp(floor(t), texels.xy, texels.zw));
  centreUv = ((vec2(texel) + 0.5) / float(shadowResolution) - tile.xy) / (tile.zw - tile.xy) + vec2(offset);
  return texel;
}
