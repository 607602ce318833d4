// The browser side of test/browser/integrations/r3f.test.js: a React Three Fiber app (the real @react-three/fiber)
// that adds skin scattering as the README says, with hooks on `window.r3f` for the test: mount and
// unmount it, swap the camera as makeDefault does, render frames (frameloop "never": the test
// decides when), read the canvas, and render the same scene by hand with the three.js pass as the
// oracle. Nothing here is part of the library.
import { StrictMode, useState } from 'react';
import { createRoot } from 'react-dom/client';
import { Canvas, useThree } from '@react-three/fiber';
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import { OutputPass } from 'three/addons/postprocessing/OutputPass.js';
import { SubsurfaceScattering } from 'three-separable-sss';
import { getSubsurface } from 'three-separable-sss/stages';
import { SubsurfaceComposer, Subsurface, useSubsurfaceComposer } from 'three-separable-sss/react';

const WIDTH = 320;
const HEIGHT = 180;
let state = null; // R3F's store state, set by <Probe>
let registry = null;
let material = null;
let setMounted = null;

/** Reads R3F's state and the composer's registry out for the test. */
function Probe() {
  state = useThree();
  return null;
}

function Skin() {
  const [light, setLight] = useState(null);
  return (
    <>
      <spotLight ref={setLight} position={[0.6, 0.4, -1]} intensity={30} angle={Math.PI / 6} penumbra={0.3} />
      <hemisphereLight args={[0xffffff, 0x443333, 1.5]} />
      <SubsurfaceComposer light={light} worldUnitInMm={1000}>
        <Registry />
        <mesh>
          <torusKnotGeometry args={[0.08, 0.025, 200, 32]} />
          <meshStandardMaterial ref={(m) => { material = m; }} color="#e0b8a0" roughness={0.5}>
            <Subsurface widthMm={1} />
          </meshStandardMaterial>
        </mesh>
      </SubsurfaceComposer>
    </>
  );
}

/** Hands the enclosing composer's registry (the pass it built) to the test. */
function Registry() {
  registry = useSubsurfaceComposer();
  return null;
}

function App() {
  const [mounted, set] = useState(false);
  setMounted = set;
  return (
    <Canvas frameloop="never" dpr={1} gl={{ preserveDrawingBuffer: true, antialias: false }}
      camera={{ fov: 30, near: 0.01, far: 10, position: [0, 0, 0.6] }} style={{ width: WIDTH, height: HEIGHT }}>
      <Probe />
      {mounted && <Skin />}
    </Canvas>
  );
}

/** The canvas as RGBA floats in 0..1, rows bottom-up (GL order, as the lab's read-backs). */
function readCanvas() {
  const canvas = state.gl.domElement;
  const copy = new OffscreenCanvas(canvas.width, canvas.height);
  const ctx = copy.getContext('2d');
  ctx.drawImage(canvas, 0, 0);
  const { data } = ctx.getImageData(0, 0, canvas.width, canvas.height);
  const out = new Float32Array(data.length);
  for (let y = 0; y < canvas.height; y++) {
    for (let i = 0; i < canvas.width * 4; i++) out[(canvas.height - 1 - y) * canvas.width * 4 + i] = data[y * canvas.width * 4 + i] / 255;
  }
  return out;
}

/** The same scene rendered by hand: the three.js pass in three's EffectComposer, OutputPass, to the canvas. */
function renderByHand({ scattering = true } = {}) {
  const { gl, scene, camera, size } = state;
  const pass = new SubsurfaceScattering({ scene, camera, light: scene.getObjectByProperty('isSpotLight', true), worldUnitInMm: 1000 });
  pass.scattering = scattering;
  const composer = new EffectComposer(gl, new THREE.WebGLRenderTarget(1, 1, { type: THREE.HalfFloatType, samples: 4 }));
  // The material is R3F's, bound to R3F's pipeline too: this pipeline's own binding draws here.
  pass.makeSubsurface(material, { widthMm: 1 });
  composer.addPass(pass);
  composer.addPass(new OutputPass());
  composer.setPixelRatio(gl.getPixelRatio());
  composer.setSize(size.width, size.height);
  composer.render();
  const image = readCanvas();
  pass.dispose();
  composer.passes[1].dispose();
  composer.dispose();
  return image;
}

const ids = new WeakMap();
let nextId = 0;
/** A number per object, to tell whether the composer rebuilt its pass. */
function idOf(object) {
  if (!ids.has(object)) ids.set(object, ++nextId);
  return ids.get(object);
}
const frame = () => new Promise((resolve) => requestAnimationFrame(() => resolve()));

window.r3f = {
  THREE,
  /** Mounts (true) or unmounts (false) the skin subtree, then lets React and R3F settle. */
  async mount(on) {
    setMounted(on);
    for (let i = 0; i < 3; i++) await frame();
  },
  /** Renders `n` frames through R3F's loop. */
  async advance(n = 1) {
    for (let i = 0; i < n; i++) {
      state.advance(performance.now());
      await frame();
    }
  },
  readCanvas,
  renderByHand,
  /** A camera elsewhere, made R3F's default as drei's makeDefault does (set({ camera })). */
  swapCamera() {
    const camera = new THREE.PerspectiveCamera(40, WIDTH / HEIGHT, 0.01, 10);
    camera.position.set(0.25, 0.1, 0.45);
    camera.lookAt(0, 0, 0);
    state.set({ camera });
    return camera.uuid;
  },
  /** What three holds now (memory, programs) and what the composer built. */
  info() {
    const { gl } = state;
    const sssPrograms = (gl.info.programs ?? []).filter((p) => p.cacheKey.includes('subsurface')).length;
    return {
      textures: gl.info.memory.textures,
      geometries: gl.info.memory.geometries,
      programs: gl.info.programs?.length ?? 0,
      sssPrograms,
      cameraUuid: state.camera.uuid,
      subsurface: material ? getSubsurface(material) !== undefined : null,
      passId: registry?.pass ? idOf(registry.pass) : null,
    };
  },
};

createRoot(document.getElementById('root')).render(<StrictMode><App /></StrictMode>);
window.testReady = new Promise((resolve) => {
  const wait = () => (state ? resolve(true) : requestAnimationFrame(wait));
  wait();
});
