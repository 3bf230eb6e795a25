// Moment shadow maps (lookup/msm_filter.cpp, lookup/moment_shadow.cpp): the Hamburger 4MSM bound on
// the blurred moments (d, d², d³, d⁴), stored as float32 or at 16 bits in the optimized basis.
uniform float shadowMsmMomentBias;  // α
uniform int shadowMsmQuantized;     // 1: unorm16 in the optimized basis
// optimized_moments and power_from_optimized: Peters and Klein's supplementary listing 1, the
// sixteen numbers row by row as the paper's b · M, which GLSL's mat4 holds column by column.
const mat4 shadowOptimizedFromPower = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,    //
                                           32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,  //
                                           -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,   //
                                           39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const mat4 shadowPowerFromOptimized = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,     //
                                           0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,    //
                                           0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,    //
                                           0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const vec4 shadowOptimizedOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);
// texel_moments: the powers, or their optimized basis.
vec4 shadowMomentsOf_msm(float depth) {
  float square = depth * depth;
  vec4 power = vec4(depth, square, square * depth, square * square);
  return shadowMsmQuantized == 1 ? shadowOptimizedFromPower * power + shadowOptimizedOffset : power;
}
// stored_moments: rounded_to_unorm16 in the quantized variant.
vec4 shadowStoredMoments_msm(vec4 blurred) {
  return shadowMsmQuantized == 1 ? floor(clamp(blurred, 0.0, 1.0) * 65535.0 + 0.5) / 65535.0 : blurred;
}
// hamburger_shadow_intensity (lookup/moment_shadow.cpp), step by step.
float shadowHamburgerIntensity(vec4 moments, float z) {
  vec4 b = mix(moments, vec4(0.5, 11.0 / 32.0, 17.0 / 64.0, 29.0 / 128.0), shadowMsmMomentBias);  // step 1
  float d22 = b.y - b.x * b.x;                              // step 2: B c = (1, z, z²) by L D Lᵀ
  float l32 = (b.z - b.x * b.y) / d22;
  float d33 = b.w - b.y * b.y - l32 * l32 * d22;
  float y2 = z - b.x;
  float y3 = z * z - b.y - l32 * y2;
  float c3 = y3 / d33;
  float c2 = y2 / d22 - l32 * c3;
  float c1 = 1.0 - b.x * c2 - b.y * c3;
  float p = c2 / c3, q = c1 / c3;  // step 3: the roots z2 <= z3 of c1 + c2 x + c3 x²
  float r = sqrt(max(p * p / 4.0 - q, 0.0));
  float z2 = -p / 2.0 - r, z3 = -p / 2.0 + r;
  float g = 0.0;  // step 4: the weight nearer the light than z
  if (z > z3)
    g = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((z - z2) * (z - z3));
  else if (z > z2)
    g = (z * z3 - b.x * (z + z3) + b.y) / ((z3 - z2) * (z - z2));
  return clamp(g, 0.0, 1.0);
}
float shadowFilter_msm(int i, ShadowMapReceiver m, float rotation) {
  vec4 stored = shadowSampleMoments(i, m.uv);
  vec4 b = shadowMsmQuantized == 1 ? shadowPowerFromOptimized * (stored - shadowOptimizedOffset) : stored;
  return shadowReduceLightBleeding(1.0 - shadowHamburgerIntensity(b, m.depth), shadowBleedReduction);
}
