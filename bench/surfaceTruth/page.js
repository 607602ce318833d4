// The surface-truth bench page (browser side; bench/surfaceTruth/run.js drives it): the head as the
// speed-accuracy bench shows it, its surface truth (bench/surfaceTruth/scatter.js over the UV
// atlas, bench/surfaceTruth/atlas.js) at each pixel the camera sees, and each method's blurred
// diffuse light against it, per region. Everything goes through the library's public API.
import {
  FloatType, NearestFilter, ShaderMaterial, WebGLRenderer, WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { SubsurfaceScattering } from '/src/index.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { buildScene } from '/bench/scenes.js';
import { setLightDirection } from '/demo/headScene.js';
import { GAUSSIANS } from '/test/oracle/closedForms.js';
import { renderSurfaceAtlas } from './atlas.js';
import { coarsen, surfaceTruth } from './scatter.js';
import { classifyPixels, REGION_NAMES } from './regions.js';
import { heatMap, pngOf } from './heatMap.js';

let session = null;

/** World position (world units) and the cosine between normal and view direction, per pixel. */
const surfaceMaterial = () => new ShaderMaterial({
  vertexShader: `varying vec3 vWorld; varying vec3 vNormalView; varying vec3 vView;
    void main() {
      vWorld = ( modelMatrix * vec4( position, 1.0 ) ).xyz;
      vec4 mv = modelViewMatrix * vec4( position, 1.0 );
      vView = - mv.xyz; vNormalView = normalMatrix * normal;
      gl_Position = projectionMatrix * mv;
    }`,
  fragmentShader: `varying vec3 vWorld; varying vec3 vNormalView; varying vec3 vView;
    void main() { gl_FragColor = vec4( vWorld, dot( normalize( vNormalView ), normalize( vView ) ) ); }`,
});

/**
 * Opens the head at width × height with the light at (azimuth, elevation) degrees.
 * @param {{ width: number, height: number, lightAzimuthDeg: number, lightElevationDeg: number, widthMm?: number, atlasSize?: number, view?: number[]|null }} o
 *   view: [x, y, z, targetX, targetY, targetZ, fovDeg] for another camera than the bench's (a close-up)
 */
async function open({ width, height, lightAzimuthDeg, lightElevationDeg, widthMm = 1, atlasSize = 2048, view = null }) {
  close();
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  const built = await buildScene('head', { aspect: width / height });
  setLightDirection({ light: built.light }, lightAzimuthDeg, lightElevationDeg);
  if (view) {
    const [x, y, z, tx, ty, tz, fov] = view;
    built.camera.position.set(x, y, z);
    built.camera.lookAt(tx, ty, tz);
    built.camera.fov = fov;
    built.camera.updateProjectionMatrix();
    built.camera.updateMatrixWorld();
  }
  const mesh = built.scene.children.find((o) => o.isMesh && o.material === built.subsurface[0]);
  session = { width, height, renderer, built, mesh, widthMm, truth: null, regions: null };
  const surface = await renderSurface(width, height);
  const unscattered = await renderSetting({ method: 'none' });
  const { regions, counts } = classifyPixels({
    surface, mask: unscattered.diffuse, width, height, cameraPosition: built.camera.position.toArray(), worldUnitInMm: built.worldUnitInMm,
  });
  session.regions = regions;

  const pixels = [];
  for (let i = 0; i < width * height; i++) if (regions[i] >= 0) pixels.push(i);
  session.pixels = pixels;
  session.surface = surface;
  session.unscattered = unscattered.diffuse;
  const truth = await truthAt(atlasSize);
  const { light } = truth;
  session.truth = { pixels, light };
  // Scattering moves light, it does not make it: over the whole view the truth keeps about the
  // light of the unscattered image (less where light leaves through surfaces the camera misses).
  const sums = [0, 0, 0, 0, 0, 0];
  pixels.forEach((i, q) => { for (let c = 0; c < 3; c++) { sums[c] += light[3 * q + c]; sums[3 + c] += unscattered.diffuse[4 * i + c]; } });
  const gl = renderer.getContext();
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  return {
    webgl: { renderer: gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER), version: gl.getParameter(gl.VERSION) },
    truthOverUnscattered: [0, 1, 2].map((c) => sums[c] / sums[3 + c]),
    atlasSize, atlasTexels: truth.atlasTexels, coarseSamples: truth.coarseSamples, spacingsMm: truth.spacingsMm,
    localShare: truth.localShare, atlasMs: truth.atlasMs, truthMs: truth.truthMs, pixels: pixels.length, regionPixels: counts, regionNames: REGION_NAMES,
  };
}

/** The truth at the session's pixels from an atlas of `atlasSize`² texels (and its 4 × 4 merge). */
async function truthAt(atlasSize) {
  const { renderer, built, mesh, widthMm, height, pixels, surface, unscattered } = session;
  const started = performance.now();
  const atlas = await renderSurfaceAtlas({ renderer, built, mesh, widthMm, viewHeight: height, size: atlasSize });
  const levels = [atlas, coarsen(atlas, atlasSize)];
  const atlasMs = performance.now() - started;
  const queryMm = new Float64Array(3 * pixels.length);
  const queryLight = new Float64Array(3 * pixels.length);
  pixels.forEach((i, q) => {
    for (let a = 0; a < 3; a++) {
      queryMm[3 * q + a] = surface[4 * i + a] * built.worldUnitInMm;
      queryLight[3 * q + a] = unscattered[4 * i + a];
    }
  });
  const truthStarted = performance.now();
  const truth = surfaceTruth({ levels, queryMm, queryLight, gaussians: GAUSSIANS.skin, widthMm });
  return {
    ...truth, atlasMs, truthMs: performance.now() - truthStarted, atlasTexels: atlas.areaMm2.length, coarseSamples: levels[1].areaMm2.length,
  };
}

/**
 * ‖value − truth‖ / ‖no scattering − truth‖ per region and over all, RGB summed.
 * @param {(q: number, c: number) => number} valueAt query q's channel c
 */
function relativeByRegion(valueAt) {
  const { truth, regions, unscattered } = session;
  const n = REGION_NAMES.length;
  const errorSq = new Float64Array(n + 1);
  const effectSq = new Float64Array(n + 1);
  truth.pixels.forEach((i, q) => {
    for (let c = 0; c < 3; c++) {
      const t = truth.light[3 * q + c];
      for (const r of [regions[i], n]) {
        errorSq[r] += (valueAt(q, c) - t) ** 2;
        effectSq[r] += (unscattered[4 * i + c] - t) ** 2;
      }
    }
  });
  return Object.fromEntries([...REGION_NAMES, 'all'].map((name, r) => [name, Math.sqrt(errorSq[r] / effectSq[r])]));
}

/**
 * How far the truth itself moves with its sampling: the truth from an atlas of `atlasSize`²
 * texels against the session's, in the same measure as a setting's error. A setting's error
 * below this is within the truth's own uncertainty.
 */
async function truthUncertainty(atlasSize) {
  const other = await truthAt(atlasSize);
  return { atlasSize, atlasTexels: other.atlasTexels, relative: relativeByRegion((q, c) => other.light[3 * q + c]) };
}

/** The surface pass at width × height: world position (world units) and facing cosine. */
async function renderSurface(width, height) {
  const { renderer, built, mesh } = session;
  renderer.setSize(width, height, false);
  const target = new WebGLRenderTarget(width, height, { type: FloatType, minFilter: NearestFilter, magFilter: NearestFilter });
  const material = surfaceMaterial();
  const own = mesh.material;
  const background = built.scene.background;
  try {
    mesh.material = material;
    built.scene.background = null;
    renderer.setRenderTarget(target);
    renderer.setClearColor(0x000000, 0);
    renderer.clear();
    renderer.render(built.scene, built.camera);
    renderer.setRenderTarget(null);
    return await readRenderTargetFloats(renderer, target);
  } finally {
    mesh.material = own;
    built.scene.background = background;
    target.dispose();
    material.dispose();
  }
}

function close() {
  if (!session) return;
  session.renderer.dispose();
  session.renderer.forceContextLoss();
  session = null;
}

/**
 * One frame of the pipeline with `setting` ({ method: 'none' } for no scattering, or the options of
 * SubsurfaceScattering, e.g. { method: 'footprint', samples: 'auto' }); returns the diffuse light
 * before and after the blur (RGBA floats, alpha: the subsurface mask).
 */
async function renderSetting(setting, width = session.width, height = session.height) {
  const { renderer, built, widthMm } = session;
  renderer.setSize(width, height, false);
  const none = setting.method === 'none';
  const sss = new SubsurfaceScattering({
    scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: built.worldUnitInMm, type: FloatType,
    ...(none ? {} : setting),
  });
  sss.makeSubsurface(built.subsurface[0], { widthMm });
  if (none) sss.scattering = false;
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(width, height, { type: FloatType }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  try {
    composer.render();
    const diffuse = await readRenderTargetFloats(renderer, sss.scenePass.renderTarget, 1);
    const scattered = none ? diffuse : await readRenderTargetFloats(renderer, sss.scatteredTarget);
    return { diffuse, scattered };
  } finally {
    sss.dispose();
    composer.dispose();
  }
}

/**
 * A setting's error against the truth: ‖method − truth‖ / ‖no scattering − truth‖ over each
 * region's pixels (RGB summed), and a heat map of |method − truth| (sum of channels).
 * @param {object} setting as renderSetting
 * @param {{ heatMapMax?: number }} [o]
 */
async function measure(setting, { heatMapMax = 0.05 } = {}) {
  const { truth, regions, width, height } = session;
  const { scattered } = await renderSetting(setting);
  const absolute = new Float32Array(width * height);
  truth.pixels.forEach((i, q) => {
    for (let c = 0; c < 3; c++) absolute[i] += Math.abs(scattered[4 * i + c] - truth.light[3 * q + c]);
  });
  const relative = relativeByRegion((q, c) => scattered[4 * truth.pixels[q] + c]);
  return { relative, heatMap: await heatMap(absolute, width, height, heatMapMax, regions) };
}

/** The truth, the unscattered and a setting's light as PNGs (linear → sRGB-ish gamma 2.2). */
async function images(setting) {
  const { truth, unscattered, width, height } = session;
  const truthImage = new Float32Array(4 * width * height);
  truth.pixels.forEach((i, q) => { for (let c = 0; c < 3; c++) truthImage[4 * i + c] = truth.light[3 * q + c]; });
  const { scattered } = await renderSetting(setting);
  // Linear light to 8 bits with a 2.2 gamma (near sRGB), for a look.
  const toPng = (data) => pngOf(width, height, (i) => [0, 1, 2].map((c) => Math.min(255, Math.round(255 * Math.max(data[4 * i + c], 0) ** (1 / 2.2)))));
  return { truth: await toPng(truthImage), unscattered: await toPng(unscattered), setting: await toPng(scattered) };
}

window.surfaceTruthBench = { open, measure, truthUncertainty, images, close };
