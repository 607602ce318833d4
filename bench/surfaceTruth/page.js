// The surface-truth bench page (browser side; bench/surfaceTruth/run.js drives it): the head as the
// speed-accuracy bench shows it (or a close-up, or the flat slab), its surface truth
// (bench/surfaceTruth/scatter.js over the mesh's triangles) at each pixel the camera sees, and each
// method's blurred diffuse light against it, per region. The truth scatters the light the pipeline
// blurs: at surface points the camera sees, the diffuse attachment of the same frame, at the same
// resolution; the UV atlas's light (bench/surfaceTruth/atlas.js) only where the camera does not
// see. That light leaves the pipeline's transmittance out: the truth makes its own, light entering
// the far side of a thin part reaching the near side through it (3D distances), so a method's
// transmittance is measured against it, not built into it. Everything goes through the library's
// public API. (One file over 300 lines: open, the truth, measure, costs and images share one session.)
import {
  FloatType, NearestFilter, ShaderMaterial, WebGLRenderer, WebGLRenderTarget,
} from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { SubsurfaceScattering } from '/src/index.js';
import { LightDepthTarget } from '/src/stages.js';
import { useDenseReference } from '/src/internals.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { GpuStageTimer, median, sssStageTimes } from '/dev/gpuTimer.js';
import { buildScene } from '/bench/scenes.js';
import { setLightDirection } from '/demo/headScene.js';
import { GAUSSIANS } from '/test/oracle/closedForms.js';
import { renderSurfaceAtlas } from './atlas.js';
import { surfaceTruth } from './scatter.js';
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
 * Opens a scene at width × height with the light at (azimuth, elevation) degrees.
 * @param {{ width: number, height: number, lightAzimuthDeg?: number, lightElevationDeg?: number, widthMm?: number, atlasSize?: number, density?: number, view?: number[]|null, scene?: 'head'|'slab' }} o
 *   view: [x, y, z, targetX, targetY, targetZ, fovDeg] for another camera than the bench's (a close-up);
 *   density: the truth's samples per area (1: bench/surfaceTruth/scatter.js's rule); truthLight:
 *   the truth computed before for the same configuration (truthLight()), instead of computing it;
 *   truthIdealBlurs: its ideal blurs (truthIdealBlurs()), with it
 */
async function open({ width, height, lightAzimuthDeg = 0, lightElevationDeg = 0, widthMm = 1, atlasSize = 2048, density = 1, view = null, scene = 'head', truthLight = null, truthIdealBlurs = null }) {
  close();
  const renderer = new WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  const built = await buildScene(scene, { aspect: width / height });
  if (scene === 'head') setLightDirection({ light: built.light }, lightAzimuthDeg, lightElevationDeg);
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
  session.triangles = trianglesOf(mesh, built.worldUnitInMm);
  // truthLight: a truth computed before for this configuration (its light per pixel, as truthLight() gives it).
  const cachedBlurs = truthIdealBlurs && Object.fromEntries(Object.entries(truthIdealBlurs).map(([name, light]) => [name, Float64Array.from(light)]));
  const truth = truthLight ? { light: Float64Array.from(truthLight), idealBlurs: cachedBlurs, cached: true } : await truthAt({ atlasSize, density, idealBlurs: true });
  if (!truthLight && built.light) { // the same with the light's view of the surface too (a translucent shadow map's)
    const { idealBlurs: both } = await truthAt({ atlasSize, density, idealBlurs: true, lightSees: await lightVisibility() });
    truth.idealBlurs = { ...truth.idealBlurs, seenOrLit: both.seen, seenOrLitTrueArea: both.seenTrueArea };
  }
  if (truth.light.length !== 3 * pixels.length) throw new RangeError(`open: truthLight must hold 3 × ${pixels.length} values, got ${truth.light.length}`);
  const { light } = truth;
  session.truth = { pixels, light, idealBlurs: truth.idealBlurs ?? null };
  // Scattering moves light, it does not make it: over the whole view the truth keeps about the
  // light of the unscattered image (less where light leaves through surfaces the camera misses).
  const sums = [0, 0, 0, 0, 0, 0];
  pixels.forEach((i, q) => { for (let c = 0; c < 3; c++) { sums[c] += light[3 * q + c]; sums[3 + c] += unscattered.diffuse[4 * i + c]; } });
  const gl = renderer.getContext();
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const { light: _, idealBlurs: __, ...stats } = truth;
  return {
    webgl: { renderer: gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER), version: gl.getParameter(gl.VERSION) },
    truthOverUnscattered: [0, 1, 2].map((c) => sums[c] / sums[3 + c]),
    ...stats, pixels: pixels.length, regionPixels: counts, regionNames: REGION_NAMES,
  };
}

/** The mesh's triangles in world millimetres, with their uvs (non-indexed, 9 and 6 numbers each). */
function trianglesOf(mesh, worldUnitInMm) {
  mesh.updateMatrixWorld();
  const { geometry } = mesh;
  const position = geometry.attributes.position;
  const { uv } = geometry.attributes;
  const count = geometry.index ? geometry.index.count : position.count;
  const corner = (k) => (geometry.index ? geometry.index.getX(k) : k);
  const m = mesh.matrixWorld.elements;
  const positionMm = new Float64Array(3 * count);
  const uvs = new Float64Array(2 * count);
  for (let k = 0; k < count; k++) {
    const v = corner(k);
    const [x, y, z] = [position.getX(v), position.getY(v), position.getZ(v)];
    for (let a = 0; a < 3; a++) positionMm[3 * k + a] = (m[a] * x + m[4 + a] * y + m[8 + a] * z + m[12 + a]) * worldUnitInMm;
    uvs[2 * k] = uv.getX(v);
    uvs[2 * k + 1] = uv.getY(v);
  }
  return { positionMm, uv: uvs };
}

/** A surface point is the camera's when it lies this close (mm) in depth to its pixel's surface, plus the pixel's own depth span. */
const VISIBLE_DEPTH_MM = 0.5;
/** The pixel's depth span is counted up to this many pixel footprints (a facing cosine of 0.24). */
const MAX_DEPTH_SPAN_PIXELS = 4;

/**
 * The light entering at a surface point, and whether the camera sees it (a fourth number, 1 or 0,
 * for the ideal blurs; with `lightSees`, whether the camera or the light sees it): its
 * camera pixel's diffuse light where the camera sees it
 * (inside the image, on a subsurface pixel whose surface lies at the point's distance within
 * VISIBLE_DEPTH_MM plus the pixel's depth span at its facing angle), else the atlas's.
 * Counts where each read came from in `counts`.
 */
function lightOfSurface(atlas, counts, lightSees = null) {
  const { width, height, built, surface, unscattered } = session;
  const { camera, worldUnitInMm } = built;
  camera.updateMatrixWorld();
  const viewProjection = camera.projectionMatrix.clone().multiply(camera.matrixWorldInverse).elements;
  const eyeWorld = camera.position.toArray();
  const eye = eyeWorld.map((x) => x * worldUnitInMm);
  const pixelPerDepth = 2 / (camera.projectionMatrix.elements[5] * height); // pixel footprint / distance
  const out = [0, 0, 0, 1]; // reused: the caller copies it; out[3]: 1 where the camera sees the point
  return (pointMm, uv) => {
    const x = pointMm[0] / worldUnitInMm;
    const y = pointMm[1] / worldUnitInMm;
    const z = pointMm[2] / worldUnitInMm;
    const e = viewProjection;
    const w = e[3] * x + e[7] * y + e[11] * z + e[15];
    if (w > 0) {
      const px = Math.floor((((e[0] * x + e[4] * y + e[8] * z + e[12]) / w + 1) / 2) * width);
      const py = Math.floor((((e[1] * x + e[5] * y + e[9] * z + e[13]) / w + 1) / 2) * height); // GL rows
      const i = py * width + px;
      if (px >= 0 && py >= 0 && px < width && py < height && unscattered[4 * i + 3] > 0) {
        const distanceMm = Math.sqrt((pointMm[0] - eye[0]) ** 2 + (pointMm[1] - eye[1]) ** 2 + (pointMm[2] - eye[2]) ** 2);
        const pixelDistanceMm = worldUnitInMm * Math.sqrt((surface[4 * i] - eyeWorld[0]) ** 2 + (surface[4 * i + 1] - eyeWorld[1]) ** 2 + (surface[4 * i + 2] - eyeWorld[2]) ** 2);
        const facing = Math.min(Math.max(surface[4 * i + 3], 1e-3), 1);
        const spanMm = pixelPerDepth * pixelDistanceMm * Math.min(Math.sqrt(1 - facing * facing) / facing, MAX_DEPTH_SPAN_PIXELS);
        if (Math.abs(distanceMm - pixelDistanceMm) <= VISIBLE_DEPTH_MM + spanMm) {
          counts.camera++;
          out[0] = unscattered[4 * i]; out[1] = unscattered[4 * i + 1]; out[2] = unscattered[4 * i + 2]; out[3] = 1;
          return out;
        }
      }
    }
    out[3] = lightSees !== null && lightSees(x, y, z) ? 1 : 0;
    if (atlas.lightAt(uv[0], uv[1], out)) { counts.atlas++; return out; }
    counts.missed++;
    out[0] = 0; out[1] = 0; out[2] = 0; out[3] = 0;
    return out;
  };
}

/**
 * The truth at the session's pixels: over the mesh at `density` (bench/surfaceTruth/scatter.js),
 * the camera's light where it sees, an atlas of `atlasSize`² texels elsewhere; with
 * `idealBlurs`, the ideal blurs of what is seen (by the camera, or by the camera or `lightSees`).
 */
async function truthAt({ atlasSize = 2048, density = 1, idealBlurs = false, lightSees = null } = {}) {
  const { renderer, built, mesh, widthMm, height, pixels, surface, unscattered, triangles } = session;
  const started = performance.now();
  const atlas = await renderSurfaceAtlas({ renderer, built, mesh, widthMm, viewHeight: height, size: atlasSize });
  const atlasMs = performance.now() - started;
  const queryMm = new Float64Array(3 * pixels.length);
  const queryLight = new Float64Array(3 * pixels.length);
  const queryPixelMm = new Float64Array(pixels.length);
  const eye = built.camera.position.toArray();
  const pixelPerDepth = 2 / (built.camera.projectionMatrix.elements[5] * height);
  pixels.forEach((i, q) => {
    for (let a = 0; a < 3; a++) {
      queryMm[3 * q + a] = surface[4 * i + a] * built.worldUnitInMm;
      queryLight[3 * q + a] = unscattered[4 * i + a];
    }
    queryPixelMm[q] = pixelPerDepth * Math.hypot(...[0, 1, 2].map((a) => surface[4 * i + a] - eye[a])) * built.worldUnitInMm;
  });
  // The light is read on pieces of half the median pixel footprint: finer than the pixels' light.
  const lightEdgeMm = medianOf(queryPixelMm) / 2;
  const counts = { camera: 0, atlas: 0, missed: 0 };
  const truthStarted = performance.now();
  const truth = surfaceTruth({
    triangles, lightAt: lightOfSurface(atlas, counts, lightSees), queryMm, queryLight, queryPixelMm, gaussians: GAUSSIANS.skin, widthMm, lightEdgeMm, density, idealBlurs,
  });
  const reads = counts.camera + counts.atlas + counts.missed;
  return {
    light: truth.light, idealBlurs: truth.idealBlurs, atlasSize, density, atlasMs, truthMs: performance.now() - truthStarted, lightEdgeMm,
    localShare: truth.localShare, pieces: truth.pieces, lightReads: reads,
    readShares: Object.fromEntries(Object.entries(counts).map(([k, n]) => [k, n / reads])),
  };
}

/** How far (mm) a point may lie behind the surface the light's depth map holds and still be that surface, beside a texel's width. */
const LIGHT_SEES_DEPTH_MM = 1;

/**
 * Whether the light sees a point (world units): the point's depth along the light's axis is within
 * LIGHT_SEES_DEPTH_MM plus a texel's width of the surface one of the four nearest texels of the
 * library's own light depth map holds (LightDepthTarget, 2048²: what a translucent shadow map of
 * the light's view would hold).
 */
async function lightVisibility() {
  const { renderer, built } = session;
  const view = new LightDepthTarget(built.light, { size: 2048 });
  try {
    view.render(renderer, built.scene);
    const depth = await readRenderTargetFloats(renderer, view.renderTarget);
    const { camera, size } = view;
    const viewMatrix = camera.matrixWorldInverse.elements;
    const projection = camera.projectionMatrix.clone().multiply(camera.matrixWorldInverse).elements;
    const texelWorld = camera.isOrthographicCamera ? Math.max(camera.right - camera.left, camera.top - camera.bottom) / size : null;
    const toleranceBase = LIGHT_SEES_DEPTH_MM / built.worldUnitInMm;
    return (x, y, z) => {
      const e = projection;
      const w = e[3] * x + e[7] * y + e[11] * z + e[15];
      if (!(w > 0)) return false;
      const u = (((e[0] * x + e[4] * y + e[8] * z + e[12]) / w + 1) / 2) * size - 0.5;
      const v = (((e[1] * x + e[5] * y + e[9] * z + e[13]) / w + 1) / 2) * size - 0.5;
      if (!(u >= -0.5 && v >= -0.5 && u < size - 0.5 && v < size - 0.5)) return false;
      const pointDepth = -(viewMatrix[2] * x + viewMatrix[6] * y + viewMatrix[10] * z + viewMatrix[14]);
      const tolerance = toleranceBase + (texelWorld ?? (2 * pointDepth) / (camera.projectionMatrix.elements[0] * size));
      const u0 = Math.floor(u);
      const v0 = Math.floor(v);
      for (let k = 0; k < 4; k++) {
        const tu = Math.min(Math.max(u0 + (k & 1), 0), size - 1);
        const tv = Math.min(Math.max(v0 + (k >> 1), 0), size - 1);
        const recorded = depth[4 * (tv * size + tu)];
        if (recorded > 0 && Math.abs(pointDepth - recorded) <= tolerance) return true;
      }
      return false;
    };
  } finally {
    view.dispose();
  }
}

/** The median of a typed array (a copy is sorted). */
function medianOf(values) {
  const sorted = Float64Array.from(values).sort();
  return sorted[Math.floor(sorted.length / 2)];
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
 * Per region: the mean of value − truth per channel, over the mean truth (R, G, B): whether a
 * setting is too dark (negative) or too bright there, and in which colour.
 * @param {(q: number, c: number) => number} valueAt query q's channel c
 */
function biasByRegion(valueAt) {
  const { truth, regions } = session;
  const n = REGION_NAMES.length;
  const difference = new Float64Array(3 * (n + 1));
  const sum = new Float64Array(3 * (n + 1));
  truth.pixels.forEach((i, q) => {
    for (const r of [regions[i], n]) {
      for (let c = 0; c < 3; c++) {
        difference[3 * r + c] += valueAt(q, c) - truth.light[3 * q + c];
        sum[3 * r + c] += truth.light[3 * q + c];
      }
    }
  });
  return Object.fromEntries([...REGION_NAMES, 'all'].map((name, r) => [name, [0, 1, 2].map((c) => difference[3 * r + c] / sum[3 * r + c])]));
}

/**
 * How far the truth itself moves with its sampling: the truth at another density or atlas size
 * ({ density, atlasSize }, as truthAt) against the session's, in the same measure as a setting's
 * error. A setting's error below this is within the truth's own uncertainty.
 */
async function truthUncertainty(o) {
  const { light, ...other } = await truthAt(o);
  return { ...other, relative: relativeByRegion((q, c) => light[3 * q + c]) };
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
 * One frame of the pipeline with `setting` ({ method: 'none' }: no scattering and no transmittance,
 * the light the truth scatters; or the options of SubsurfaceScattering, e.g. { method: 'footprint',
 * samples: 'auto' }, transmittance: false to turn it off, denseReference: true for the dense 2D
 * reference); returns the diffuse light
 * before and after the blur (RGBA floats, alpha: not 0 on the subsurface mask: the depth it carries).
 */
async function renderSetting(setting) {
  const { renderer } = session;
  const { sss, composer, none } = pipelineOf(setting);
  try {
    composer.render();
    const diffuse = await readRenderTargetFloats(renderer, sss._scenePass.renderTarget, 1);
    const scattered = none ? diffuse : await readRenderTargetFloats(renderer, sss._blur.scatteredTarget);
    return { diffuse, scattered };
  } finally {
    sss.dispose();
    composer.dispose();
  }
}

/** The pipeline of `setting` (as renderSetting) in a composer of its own, at the session's size. */
function pipelineOf(setting) {
  const { renderer, built, widthMm, width, height } = session;
  renderer.setSize(width, height, false);
  const none = setting.method === 'none';
  const { transmittance = !none, denseReference = false, ...options } = none ? {} : setting; // transmittance: the pipeline's setter
  const sss = new SubsurfaceScattering({
    scene: built.scene, camera: built.camera, light: built.light, worldUnitInMm: built.worldUnitInMm, type: FloatType, ...options,
  });
  sss.makeSubsurface(built.subsurface[0], { widthMm });
  if (none) sss.scattering = false;
  if (denseReference) useDenseReference(sss);
  if (!transmittance && sss.transmittance) sss.transmittance = false;
  const composer = new EffectComposer(renderer, new WebGLRenderTarget(width, height, { type: FloatType }));
  composer.renderToScreen = false;
  composer.addPass(sss);
  return { sss, composer, none };
}

/**
 * Each setting's SSS time (ms: blurH + blurV, or dense) from EXT_disjoint_timer_query_webgl2 (CPU
 * times on SwiftShader): its median over `rounds` rounds in which every setting is timed in turn,
 * `reruns` re-runs of its SSS stage over one frame's scene split each.
 * @param {[string, object][]} settings name and options (as renderSetting)
 * @returns {Promise<Record<string, number>>}
 */
async function costs(settings, { rounds = 3, reruns = 2 } = {}) {
  const { renderer } = session;
  const timer = new GpuStageTimer(renderer);
  const rigs = settings.map(([name, setting]) => ({ name, ...pipelineOf(setting), ms: [] }));
  const pixel = new Float32Array(4);
  try {
    for (let r = 0; r < rounds; r++) {
      for (const rig of rigs) {
        rig.sss.stageTimer = timer;
        timer.recording = false;
        rig.composer.render();
        timer.recording = true;
        for (let k = 0; k < reruns; k++) {
          rig.sss._renderScattering(renderer);
          renderer.readRenderTargetPixels(rig.sss._blur.scatteredTarget, 0, 0, 1, 1, pixel);
        }
        timer.recording = false;
        rig.ms.push(...sssStageTimes(await timer.collect()));
      }
    }
    return Object.fromEntries(rigs.map((rig) => [rig.name, median(rig.ms)]));
  } finally {
    for (const rig of rigs) { rig.sss.dispose(); rig.composer.dispose(); }
    timer.dispose();
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
  return { relative, bias: biasByRegion((q, c) => scattered[4 * truth.pixels[q] + c]), heatMap: await heatMap(absolute, width, height, heatMapMax, regions) };
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

/** The session's truth, rgb per subsurface pixel (in the order of the pixels), to be saved and given back to open. */
const truthLight = () => Array.from(session.truth.light);

/** The truth's ideal blurs (to keep beside truthLight()), or null where it has none. */
const truthIdealBlurs = () => {
  const blurs = session.truth.idealBlurs;
  return blurs && Object.fromEntries(Object.entries(blurs).map(([name, light]) => [name, Array.from(light)]));
};

/**
 * The ideal blurs of what is seen (bench/surfaceTruth/scatter.js's idealBlursOf: `seen`, the
 * light the camera sees, each Gaussian's mean over the surface it sees; `seenTrueArea`, that with
 * the true area within reach), and the same with the surface the light sees too (`seenOrLit`,
 * `seenOrLitTrueArea`: the light's view, as a translucent shadow map holds it), in the measure of
 * a setting's error; null where the truth has none (kept from a run before they were computed).
 */
function idealBlurs() {
  const blurs = session.truth.idealBlurs;
  if (!blurs) return null;
  return Object.fromEntries(Object.entries(blurs).map(([name, light]) => {
    const valueAt = (q, c) => light[3 * q + c];
    return [name, { relative: relativeByRegion(valueAt), bias: biasByRegion(valueAt) }];
  }));
}

window.surfaceTruthBench = { open, measure, idealBlurs, truthUncertainty, images, costs, truthLight, truthIdealBlurs, close };
