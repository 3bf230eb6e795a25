// Stage 1's declarations: the drawn map and its tile (u0, v0, u1, v1) in the texture, its mask's
// half-planes (a, b, c): a u + b v + c >= 0 (maps/map_mask.hpp; GL_CLIP_DISTANCE1.. on for those it
// has), and whether the clip space's depth runs over [0, w] (a reversed format: glClipControl's
// GL_ZERO_TO_ONE) or [−w, w].
uniform int shadowDrawnMap;
uniform vec4 shadowDrawnViewport;
uniform vec3 shadowDrawnMask[shadowMaxMaskEdges];
out float gl_ClipDistance[1 + shadowMaxMaskEdges];  // sized: caster_position indexes it in a loop
uniform int shadowDepthZeroToOne;
