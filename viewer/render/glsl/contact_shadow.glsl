// Stage 2, contact shadows: contact_visibility (lookup/contact_shadow.cpp) step by step, in the
// camera's depth image ShadowMapPass draws before stage 2 (render/contact_depth_image.hpp): the
// same samples, the window depth bilinear between the four pixel centres around each, the same
// compare of view depths.
uniform sampler2D shadowContactDepth;     // the window's depth in [0, 1]
uniform mat4 shadowContactClipFromWorld;  // the camera's projection × view, in the setup's coordinates
uniform mat4 shadowContactWorldFromClip;  // its inverse
uniform vec3 shadowContactEye;
uniform vec3 shadowContactViewAxis;      // unit: a point's view depth is dot(p − eye, axis)
uniform ivec2 shadowContactImageOrigin;  // the renderer's lower-left pixel in the window
uniform ivec2 shadowContactImageSize;
uniform float shadowContactLength;
uniform int shadowContactSteps;
uniform float shadowContactThickness;
// window_depth_at: at continuous pixel coordinates (x right, y up; centres at whole numbers).
float shadowContactWindowDepthAt(vec2 at) {
  vec2 corner = floor(at), f = at - corner;
  ivec2 last = shadowContactImageSize - 1;
  float d00 = texelFetch(shadowContactDepth, shadowContactImageOrigin + clamp(ivec2(corner), ivec2(0), last), 0).r;
  float d10 = texelFetch(shadowContactDepth, shadowContactImageOrigin + clamp(ivec2(corner) + ivec2(1, 0), ivec2(0), last), 0).r;
  float d01 = texelFetch(shadowContactDepth, shadowContactImageOrigin + clamp(ivec2(corner) + ivec2(0, 1), ivec2(0), last), 0).r;
  float d11 = texelFetch(shadowContactDepth, shadowContactImageOrigin + clamp(ivec2(corner) + ivec2(1, 1), ivec2(0), last), 0).r;
  return mix(mix(d00, d10, f.x), mix(d01, d11, f.x), f.y);
}
float shadowContactViewDepth(vec3 p) { return dot(p - shadowContactEye, shadowContactViewAxis); }
float shadowContactVisibility(vec3 p) {
  vec3 towardLight = -surfaceAlongLight(p);
  for (int k = 1; k <= shadowContactSteps; ++k) {
    vec3 marched = p + towardLight * (shadowContactLength * float(k) / float(shadowContactSteps));
    vec4 clip = shadowContactClipFromWorld * vec4(marched, 1.0);
    if (clip.w <= 0.0) return 1.0;  // behind the eye
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThan(abs(ndc), vec2(1.0)))) return 1.0;  // off the image
    float window = shadowContactWindowDepthAt((ndc + 1.0) * 0.5 * vec2(shadowContactImageSize) - 0.5);
    if (window >= 1.0) continue;  // nothing seen there
    vec4 seen = shadowContactWorldFromClip * vec4(ndc, 2.0 * window - 1.0, 1.0);
    float behind = shadowContactViewDepth(marched) - shadowContactViewDepth(seen.xyz / seen.w);
    if (behind > 0.0 && behind < shadowContactThickness) return 0.0;
  }
  return 1.0;
}
