//VTK::Light::Impl
  // Steps 1 and 3, after VTK's lighting: the scene's fragments shaded as lit or as shadowed.
  {
    vec3 p = surfaceWorldVSOutput.xyz;
    gl_FragData[0] = surfaceColour(ambientColor, diffuseColor, opacity, p, surfaceSeenNormal(p), surfaceLit);
  }
