// The head's surface in its UV atlas (browser side): every texel of the atlas is one surface
// sample with its world position, area and diffuse light, whether the camera sees it or not.
// The light is the pipeline's own: the mesh's material made subsurface by a pipeline of its own,
// drawn with its vertices placed at their uv instead of their projection, so each texel holds the
// diffuse light (the shading, shadows and transmittance of the screen pixels) of its surface point.
import {
  DoubleSide, FloatType, NearestFilter, ShaderChunk, ShaderMaterial, WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { SubsurfaceScattering } from '/src/index.js';
import { readRenderTargetFloats } from '/dev/readback.js';

/** Vertices drawn at their uv: the atlas, texel (u, v) ↔ clip (2u − 1, 2v − 1). */
const AT_UV = 'gl_Position = vec4( uv * 2.0 - 1.0, 0.0, 1.0 );';

/** Position (world units) and area (world units² per texel, from the derivatives of position). */
const geometryMaterial = () => new ShaderMaterial({
  side: DoubleSide,
  vertexShader: `varying vec3 vWorld;
    void main() { vWorld = ( modelMatrix * vec4( position, 1.0 ) ).xyz; ${AT_UV} }`,
  fragmentShader: `varying vec3 vWorld;
    void main() { gl_FragColor = vec4( vWorld, length( cross( dFdx( vWorld ), dFdy( vWorld ) ) ) ); }`,
});

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

/**
 * Renders `mesh`'s surface into a size × size atlas.
 * @param {object} o
 * @param {import('three').WebGLRenderer} o.renderer
 * @param {{ scene, camera, light, worldUnitInMm: number }} o.built the scene as the bench builds it
 * @param {import('three').Mesh} o.mesh the subsurface mesh (its material is put back)
 * @param {number} o.widthMm
 * @param {number} o.viewHeight the camera's image height, pixels (the textures are read at its mip levels)
 * @param {number} [o.size=2048]
 * @returns {Promise<import('./scatter.js').SurfaceSamples & { texel: Uint32Array }>} covered texels only
 *   (millimetres), each with its index in the atlas
 */
export async function renderSurfaceAtlas({ renderer, built, mesh, widthMm, viewHeight, size = 2048 }) {
  const { scene, camera, light, worldUnitInMm } = built;
  const own = { material: mesh.material, frustumCulled: mesh.frustumCulled };
  const target = new WebGLRenderTarget(size, size, { type: FloatType, minFilter: NearestFilter, magFilter: NearestFilter });
  const geometry = geometryMaterial();
  const material = own.material.clone();
  // Perspective camera: a pixel spans 2 tan(fov / 2) / height world units per unit of depth.
  drawAtUv(material, { pixelWorldPerDepth: 2 / (camera.projectionMatrix.elements[5] * viewHeight), size });
  const sss = new SubsurfaceScattering({ scene, camera, light, worldUnitInMm, type: FloatType });
  sss.makeSubsurface(material, { widthMm });
  sss.scattering = false; // only the scene split's diffuse light is wanted
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(size, size, { type: FloatType }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  try {
    mesh.frustumCulled = false;
    mesh.material = geometry;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(mesh, camera);
    renderer.setRenderTarget(null);
    const surface = await readRenderTargetFloats(renderer, target);
    mesh.material = material;
    composer.render();
    const diffuse = await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 1);
    let texels = 0;
    for (let i = 0; i < size * size; i++) if (surface[4 * i + 3] > 0 && diffuse[4 * i + 3] > 0) texels++;
    const positionMm = new Float64Array(3 * texels);
    const areaMm2 = new Float64Array(texels);
    const lightOut = new Float64Array(3 * texels);
    const texel = new Uint32Array(texels);
    for (let i = 0, n = 0; i < size * size; i++) {
      if (!(surface[4 * i + 3] > 0 && diffuse[4 * i + 3] > 0)) continue;
      for (let a = 0; a < 3; a++) {
        positionMm[3 * n + a] = surface[4 * i + a] * worldUnitInMm;
        lightOut[3 * n + a] = diffuse[4 * i + a];
      }
      areaMm2[n] = surface[4 * i + 3] * worldUnitInMm * worldUnitInMm;
      texel[n] = i;
      n++;
    }
    return { positionMm, areaMm2, light: lightOut, texel };
  } finally {
    Object.assign(mesh, own);
    sss.dispose();
    composer.dispose();
    geometry.dispose();
    material.dispose();
    target.dispose();
  }
}
