// The subsurface pass's MRT outputs for WebGPURenderer: the names the material writes and the blur
// reads (the WebGL path's attachments, src/2-scene-split/subsurfaceTarget.js, by name instead of
// location). What each channel holds:
//   output   three's colour: specular + emissive of subsurface materials, full colour elsewhere
//   diffuse  rgb: the diffuse light (half float, linear HDR); a: 1 on subsurface pixels (the mask)
//   surface  (two channels) r: linear view depth (world units, 32-bit float: mm differences at metres need the
//            mantissa); g: the material's widthMm (profile mm per mm; the WebGL path stores world
//            units per profile mm: here the node divides by its worldUnitInMm)
export const ATTACHMENT_NAMES = Object.freeze({ COLOR: 'output', DIFFUSE: 'diffuse', SURFACE: 'surface' });
