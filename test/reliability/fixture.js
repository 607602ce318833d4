// The scene every reliability case starts from, the same in Node (no renderer: the calls alone)
// and in the browser (test/pages/reliability.js: with a renderer, a composer and a frame): a thin
// subsurface box over a grey background, back-lit by a SpotLight (transmittance), an ambient light,
// and a pipeline made on first use of `t.sss`. Nothing here is part of the library.

/** A profile object whose functions return NaN: what a broken custom profile looks like. */
export function nanProfile() {
  const nan = () => [NaN, NaN, NaN];
  return { name: 'nan', R: nan, marginal: nan, marginalIntegral: nan, transmittance: nan, radiusMm: () => [1, 1, 1], lengthScaleMm: 1 };
}

/**
 * Throws unless each of `values`' settings reads back from `object` as given (an assignment is
 * never ignored): for the table's 'ok' lines, in Node and in the browser.
 */
export function expectRead(object, values) {
  for (const [name, value] of Object.entries(values)) {
    if (object[name] !== value) throw new Error(`${name} reads back ${String(object[name])}, not ${String(value)} as set`);
  }
  return object;
}

/** A built-in profile with one channel, one function or one value changed (`change(profile)` returns the changed parts). */
export function changedProfile(SSS, change) {
  const skin = SSS.profiles.skin;
  return { ...skin, name: 'changed', ...change(skin) };
}

/**
 * @param {object} THREE three's module
 * @param {object} SSS the library's module
 * @param {{ renderer?: object, EffectComposer?: Function, read?: Function, width?: number, height?: number }} [gpu]
 *   in the browser: the renderer to draw with, three's EffectComposer and a float read-back
 */
export function createFixture(THREE, SSS, { renderer = null, EffectComposer = null, read = null, width = 48, height = 27 } = {}) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0.25, 0.25, 0.25);
  const camera = new THREE.PerspectiveCamera(30, width / height, 0.1, 50);
  camera.position.set(0, 0, 5);
  camera.updateMatrixWorld();
  const material = new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.6 });
  const mesh = new THREE.Mesh(new THREE.BoxGeometry(1.6, 1, 0.02), material); // 2 mm thin at 100 mm per unit
  mesh.rotation.y = 0.3;
  const light = new THREE.SpotLight(0xffffff, 40, 0, Math.PI / 5, 0.3);
  light.position.set(0.3, 0.2, -3);
  scene.add(mesh, light, light.target, new THREE.AmbientLight(0xffffff, 0.4));
  const made = [];
  let sss = null;
  let composer = null;

  const t = {
    THREE, SSS, scene, camera, material, mesh, light, renderer, width, height,
    nanProfile,
    expectRead,
    changedProfile: (change) => changedProfile(SSS, change),
    /** A pipeline of this scene with `options` (disposed with the fixture). */
    make(options = {}) {
      const pipeline = new SSS.SubsurfaceScattering({ scene, camera, light, worldUnitInMm: 100, lightDepthSize: 64, ...options });
      made.push(pipeline);
      return pipeline;
    },
    /** The fixture's pipeline, with the box made subsurface (made on first use). */
    get sss() {
      if (!sss) {
        sss = t.make();
        sss.makeSubsurface(material, { widthMm: 5 });
      }
      return sss;
    },
    /** Replaces the fixture's pipeline with one made with `options` (the box subsurface in it). */
    usePipeline(options) {
      if (composer && sss) composer.removePass(sss);
      sss = t.make(options);
      sss.makeSubsurface(material, { widthMm: 5 });
      if (composer) composer.insertPass(sss, 0);
      return sss;
    },
    /** The composer drawing the pipeline (browser only), half-float, no OutputPass. */
    get composer() {
      if (!composer) {
        if (!renderer) throw new Error('the fixture has no renderer here (Node): this case needs a frame');
        composer = new EffectComposer(renderer, new THREE.WebGLRenderTarget(width, height, { type: THREE.HalfFloatType }));
        composer.renderToScreen = false;
        composer.addPass(t.sss);
      }
      return composer;
    },
    /**
     * Draws two frames and reads the last one back: { nonFinite, black, mean } over its pixels
     * (black: the fraction with r + g + b below 1e-4).
     */
    async frame() {
      const c = t.composer;
      c.render();
      c.render();
      const data = await read(renderer, c.readBuffer);
      let nonFinite = 0;
      let black = 0;
      let sum = 0;
      const pixels = data.length / 4;
      for (let i = 0; i < data.length; i += 4) {
        const r = data[i], g = data[i + 1], b = data[i + 2];
        if (!(Number.isFinite(r) && Number.isFinite(g) && Number.isFinite(b))) nonFinite++;
        else if (r + g + b < 1e-4) black++;
        else sum += (r + g + b) / 3;
      }
      return { nonFinite, black: black / pixels, mean: sum / pixels };
    },
    dispose() {
      for (const pipeline of made) pipeline.dispose();
      composer?.dispose();
      mesh.geometry.dispose();
      material.dispose();
      scene.overrideMaterial?.dispose();
    },
  };
  return t;
}
