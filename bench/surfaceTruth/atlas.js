// The head's diffuse light in its UV atlas (browser side), for the surface points the camera does
// not see (bench/surfaceTruth/page.js reads the camera's own pixels where it does). The light is
// the pipeline's own: the mesh's material made subsurface by a pipeline of its own, drawn with its
// vertices placed at their uv instead of their projection, so each texel holds the diffuse light
// (the shading and shadows of the screen pixels; transmittance left out, as in the camera's light
// the truth reads: bench/surfaceTruth/page.js) of its surface point.
import { DoubleSide, FloatType, ShaderChunk, WebGLRenderTarget } from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { SubsurfaceScattering } from '/src/index.js';
import { readRenderTargetFloats } from '/dev/readback.js';

/** Vertices drawn at their uv: the atlas, texel (u, v) ↔ clip (2u − 1, 2v − 1). */
const AT_UV = 'gl_Position = vec4( uv * 2.0 - 1.0, 0.0, 1.0 );';

/**
 * Makes `material` (a clone the caller owns) draw at uv, both faces (a mirrored uv island winds the
 * other way). Its normal is never flipped: gl_FrontFacing says how the island is laid out in uv,
 * not which side of the surface is seen. The tangent frame keeps three's faceDirection factor: it
 * comes from derivatives along the screen, here uv, and on a mirrored island it corrects the
 * frame's handedness exactly as on a back face.
 *
 * Textures are read at the mip level the camera's pixels read them at (textureGrad with the
 * footprint of one camera pixel at the point's depth, stretched by 1 / cos of the viewing angle as
 * trilinear filtering's largest axis is): read at the atlas's own resolution, the skin's pores and
 * normal-map detail made the surface light differ from the pixels' by as much as the scattering
 * does at 640×360 (1.9 % RMS against an effect of 2.5 %).
 * @param {import('three').Material} material
 * @param {{ pixelWorldPerDepth: number, size: number }} o world units per camera pixel per unit of depth; atlas texels per side
 */
function drawAtUv(material, { pixelWorldPerDepth, size }) {
  material.side = DoubleSide;
  material.onBeforeCompile = (shader) => {
    shader.uniforms.atlasPixelWorldPerDepth = { value: pixelWorldPerDepth };
    shader.uniforms.atlasSize = { value: size };
    shader.vertexShader = shader.vertexShader.replace('#include <project_vertex>', `#include <project_vertex>\n${AT_UV}`);
    const begin = ShaderChunk.normal_fragment_begin.replace('normal *= faceDirection;', '');
    if (begin === ShaderChunk.normal_fragment_begin) throw new Error('atlas: three\'s normal_fragment_begin changed');
    shader.fragmentShader = shader.fragmentShader
      .replace('#include <normal_fragment_begin>', begin)
      .replace('void main() {', `uniform float atlasPixelWorldPerDepth;
uniform float atlasSize;
void main() {
	// One camera pixel's footprint in uv: world units per pixel at this depth, over world units per uv.
	float atlasWorldPerTexel = sqrt( length( cross( dFdx( vViewPosition ), dFdy( vViewPosition ) ) ) );
	float atlasFacing = clamp( dot( normalize( vNormal ), normalize( vViewPosition ) ), 0.25, 1.0 );
	float atlasGrad = atlasPixelWorldPerDepth * vViewPosition.z / atlasFacing / ( atlasWorldPerTexel * atlasSize );
	#undef texture2D
	#define texture2D( t, p ) textureGrad( t, p, vec2( atlasGrad, 0.0 ), vec2( 0.0, atlasGrad ) )`);
  };
  material.customProgramCacheKey = () => 'surface-truth-atlas';
}

/** A covered texel this many texels away at most stands in for an uncovered one (island borders). */
const SEARCH_TEXELS = 2;

/**
 * Renders `mesh`'s diffuse light into a size × size atlas.
 * @param {object} o
 * @param {import('three').WebGLRenderer} o.renderer
 * @param {{ scene, camera, light, worldUnitInMm: number }} o.built the scene as the bench builds it
 * @param {import('three').Mesh} o.mesh the subsurface mesh (its material is put back)
 * @param {number} o.widthMm
 * @param {number} o.viewHeight the camera's image height, pixels (the textures are read at its mip levels)
 * @param {number} [o.size=2048]
 * @returns {Promise<{ lightAt: (u: number, v: number, out: number[]) => boolean, size: number }>} the
 *   light at a uv into out: its texel's, or the nearest covered texel's within SEARCH_TEXELS; false beyond
 */
export async function renderSurfaceAtlas({ renderer, built, mesh, widthMm, viewHeight, size = 2048 }) {
  const { scene, camera, light, worldUnitInMm } = built;
  const own = { material: mesh.material, frustumCulled: mesh.frustumCulled };
  const material = own.material.clone();
  // Perspective camera: a pixel spans 2 tan(fov / 2) / height world units per unit of depth.
  drawAtUv(material, { pixelWorldPerDepth: 2 / (camera.projectionMatrix.elements[5] * viewHeight), size });
  const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm, type: FloatType });
  sss.makeSubsurface(material, { widthMm });
  sss.scattering = false; // only the scene split's diffuse light is wanted
  if (sss.transmittance) sss.transmittance = false;
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(size, size, { type: FloatType }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  let diffuse;
  try {
    mesh.frustumCulled = false;
    mesh.material = material;
    composer.render();
    diffuse = await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, 1);
  } finally {
    Object.assign(mesh, own);
    sss.dispose();
    composer.dispose();
    material.dispose();
  }
  const covered = (i, j) => i >= 0 && j >= 0 && i < size && j < size && diffuse[4 * (j * size + i) + 3] > 0;
  const lightAt = (u, v, out) => {
    const i = Math.min(Math.max(Math.floor(u * size), 0), size - 1);
    const j = Math.min(Math.max(Math.floor(v * size), 0), size - 1); // GL rows: v up, as the atlas was drawn
    for (let r = 0; r <= SEARCH_TEXELS; r++) {
      for (let dj = -r; dj <= r; dj++) for (let di = -r; di <= r; di++) {
        if (Math.max(Math.abs(di), Math.abs(dj)) !== r || !covered(i + di, j + dj)) continue;
        const k = 4 * ((j + dj) * size + i + di);
        out[0] = diffuse[k]; out[1] = diffuse[k + 1]; out[2] = diffuse[k + 2];
        return true;
      }
    }
    return false;
  };
  return { lightAt, size };
}
