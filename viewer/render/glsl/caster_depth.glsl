// Stage 1's declarations: the drawn map and its tile (u0, v0, u1, v1) in the texture, and whether the
// clip space's depth runs over [0, w] (a reversed format: glClipControl's GL_ZERO_TO_ONE) or [−w, w].
uniform int shadowDrawnMap;
uniform vec4 shadowDrawnViewport;
uniform int shadowDepthZeroToOne;
