  // Stage 1, in place of VTK's gl_Position, the viewport on the whole texture: the drawn map's
  // (u, v) placed in its tile as texture_uv places it, before the division and unrounded (a viewport
  // on the tile would round its edges to whole texels and shift the map against the CPU
  // rasterizer's by up to a texel), then in OpenGL clip space (x' = 2x - w, the same for y, and for
  // z unless its range is [0, w]: a reversed format's s, the map's reversed depth, as it is);
  // and its kind's clip distance (a paraboloid's hemisphere plane), which clips the casters where the
  // CPU rasterizer cuts them (GL_CLIP_DISTANCE0 is on for kinds with a clip distance only); and its
  // mask's half-planes, linear in (u w, v w, w), which clip them as the CPU rasterizer clips before
  // the division.
  vec4 shadowH = shadowHomogeneous(shadowDrawnMap, vertexMC.xyz);
  vec4 shadowTile = shadowDrawnViewport;
  vec2 shadowInTexture = shadowTile.xy * shadowH.w + shadowH.xy * (shadowTile.zw - shadowTile.xy);
  float shadowClipZ = shadowDepthZeroToOne == 1 ? shadowH.z : 2.0 * shadowH.z - shadowH.w;
  gl_Position = vec4(2.0 * shadowInTexture - shadowH.w, shadowClipZ, shadowH.w);
  gl_ClipDistance[0] = shadowHemisphereSide(shadowDrawnMap, vertexMC.xyz);
  for (int k = 0; k < shadowMaxMaskEdges; ++k) gl_ClipDistance[1 + k] = dot(shadowDrawnMask[k], shadowH.xyw);
