// Stage 2 (material split): the multi-target's attachments beyond three's location 0, as the
// contract names them (src/2-scene-split/subsurfaceTarget.js, as defines). Every program drawn into
// the split's call declares them: a draw without an output for an active draw buffer is refused.
layout( location = SSS_DIFFUSE_LOCATION ) out highp vec4 sssDiffuseOutput; // diffuse light (+ transmittance); a: 1 (the mask) or the depth (sssDiffuseCarriesDepth)
layout( location = SSS_SURFACE_LOCATION ) out highp vec4 sssSurfaceOutput; // r: linear view depth, g: world units per profile mm, b: profile slot
