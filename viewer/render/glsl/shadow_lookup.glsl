//VTK::Light::Impl
  // The lookup, after VTK's lighting: ShadowReader::visibility, the selected map's visibility
  // crossfaded with the next map's inside a blend band; no map counts as lit; times the contact
  // shadow where it is on (receiver_visibility). The shading is linear
  // in `lit`, so that shading with the visibility mixes the two maps' shadings by the weight and
  // shades a penumbra by the share of light it sees; the lit mask thresholds the visibility at one
  // half, as the CPU's verdicts do; the visibility output writes it as a grey level. The seen normal
  // and the position's screen derivatives are only defined in uniform control flow: taken before the
  // lookup branches. The colour is the shared surface shading's, with the overlay over it.
  {
    vec3 p = surfaceWorldVSOutput.xyz;
    vec3 n = surfaceSeenNormal(p);
    vec3 dpdx = dFdx(p), dpdy = dFdy(p);
    int i = shadowSelectMap(p);
    float w = shadowBlendWeight(i, p);
    float rotation = shadowPixelRotation();
    float visibility = 1.0;
    if (i >= 0)
      visibility = w > 0.0 ? mix(shadowMapVisibility(i, p, n, rotation), shadowMapVisibility(i + 1, p, n, rotation), w)
                           : shadowMapVisibility(i, p, n, rotation);
    if (shadowContactOn == 1 && visibility > 0.0) visibility *= shadowContactVisibility(p);
    float lit = shadowLitThreshold == 1 ? (visibility < 0.5 ? 0.0 : 1.0) : visibility;
    vec4 colour = surfaceColour(ambientColor, diffuseColor, opacity, p, n, lit);
    gl_FragData[0] = shadowOverlaid(colour, i, w, p, dpdx, dpdy);
  }
