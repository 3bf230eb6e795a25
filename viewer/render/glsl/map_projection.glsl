// Both stages: each map's kind (Projection), and the shaders' stand-in for the CPU's infinities
// (float32 holds up to 3.4e38). Then each registered kind's own file and the functions that call the
// map's kind: shadowHomogeneous, shadowHemisphereSide, shadowUvDerivative, shadowDepthSlope and
// shadowDistanceBackToDepth, written from the descriptors (render/projection_glsl.cpp).
uniform int shadowMapProjection[shadowMaxMaps];
const float shadowUnbounded = 1e30;
