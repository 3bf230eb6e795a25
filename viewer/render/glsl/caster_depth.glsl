// Stage 1's declarations: the drawn map and its tile (u0, v0, u1, v1) in the texture.
uniform int shadowDrawnMap;
uniform vec4 shadowDrawnViewport;
