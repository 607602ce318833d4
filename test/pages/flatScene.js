// The analytic accuracy scene, shared by the WebGL lab (lab.js) and the WebGPURenderer lab
// (webgpu.js) so both renderers are measured on the same pixels: a flat subsurface plane seen
// straight on by an orthographic camera at exactly `pxPerMm` pixels per profile millimetre (1 world
// unit = 1 mm, widthMm 1), lit evenly from the camera (a white Lambert surface: diffuse light =
// albedo). Its albedo varies along the plane's x axis, turned by `angleDeg` on screen: 'cosines' is
// 0.5 + 0.1 Σ cos(2π f_k x + φ_k) (f in cycles per mm), 'step' is 1 for x ≥ 0 and `low` below (the
// edge on a pixel boundary through the view's centre), 'spot' one lit pixel (albedo 1, the rest `low`)
// just up and right of the view's centre, the plane's texels on the pixels (`angleDeg` 0 only).
// Nothing here is part of the library.
import * as THREE from 'three';

/** A float DataTexture from f(x, y) → [r, g, b]; nearest filtering so edges stay hard. */
export function dataTexture(width, height, f) {
  const data = new Float32Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) data.set([...f(x, y), 1], (y * width + x) * 4);
  }
  const texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  texture.minFilter = texture.magFilter = THREE.NearestFilter;
  texture.needsUpdate = true;
  return texture;
}

/**
 * @returns {{ scene, camera, material, map }} the plane's material is a MeshStandardMaterial
 *   (the caller makes it subsurface its renderer's way)
 */
export function flatScene({ width, height, pxPerMm, pattern, frequencies = [], phases = [], angleDeg = 0, low = 0.05 }) {
  const scene = new THREE.Scene();
  const halfW = width / (2 * pxPerMm);
  const halfH = height / (2 * pxPerMm);
  const camera = new THREE.OrthographicCamera(-halfW, halfW, halfH, -halfH, 1, 1000);
  camera.position.set(0, 0, 100);
  camera.updateMatrixWorld();
  const size = 2.5 * Math.max(halfW, halfH); // covers the view at any angle
  let map;
  if (pattern === 'step') {
    map = dataTexture(2, 1, (x) => (x === 0 ? [low, low, low] : [1, 1, 1]));
  } else if (pattern === 'spot') {
    if (angleDeg !== 0) throw new RangeError(`flatScene: the spot is on the pixel grid, angleDeg must be 0, got ${angleDeg}`);
    // One texel per pixel: the plane spans 2 · size mm = texels pixels, its edge on a pixel boundary.
    const texels = Math.round(2 * size * pxPerMm);
    if (Math.abs(texels - 2 * size * pxPerMm) > 1e-6 || texels % 2 !== 0) throw new RangeError(`flatScene: the spot needs whole pixels across the plane, got ${2 * size * pxPerMm}`);
    map = dataTexture(texels, texels, (x, y) => (x === texels / 2 && y === texels / 2 ? [1, 1, 1] : [low, low, low]));
  } else {
    const texels = 8192;
    map = dataTexture(texels, 1, (i) => {
      const x = ((i + 0.5) / texels - 0.5) * 2 * size;
      const v = 0.5 + frequencies.reduce((sum, f, k) => sum + 0.1 * Math.cos(2 * Math.PI * f * x + (phases[k] ?? 0)), 0);
      return [v, v, v];
    });
    map.minFilter = map.magFilter = THREE.LinearFilter;
  }
  const material = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 1, metalness: 0, map });
  const plane = new THREE.Mesh(new THREE.PlaneGeometry(2 * size, 2 * size), material);
  plane.rotation.z = (angleDeg * Math.PI) / 180;
  const light = new THREE.DirectionalLight(0xffffff, Math.PI);
  light.position.set(0, 0, 10);
  scene.add(plane, light, light.target);
  return { scene, camera, material, map, plane };
}

/**
 * The frame test's scene (test/browser/pipelineFrame.test.js; the WebGPU node's box test, test/pages/webgpu.js's
 * boxFrames): a sphere (`skin`: noise albedo, seeded) over an ordinary floor, a second one
 * (`skinBehind`) half hidden behind it, an ordinary box in front of both; a directional light
 * casting shadows; the camera at `aspect`. `subsurface`: the two spheres (three's materials:
 * the caller makes them subsurface).
 */
export function spheresScene(aspect) {
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(30, aspect, 0.5, 50);
  camera.position.set(0, 0.6, 8);
  camera.lookAt(0, 0, 0);
  let seed = 7;
  const noise = () => ((seed = (seed * 16807) % 2147483647) / 2147483647);
  const map = dataTexture(32, 32, () => { const v = 0.1 + 0.9 * noise(); return [v, 0.8 * v, 0.6 * v]; });
  const skin = new THREE.MeshStandardMaterial({ color: 0xffffff, roughness: 0.6, map });
  const skinBehind = new THREE.MeshStandardMaterial({ color: 0xffccaa, roughness: 0.8 });
  const front = new THREE.Mesh(new THREE.SphereGeometry(0.9, 48, 32), skin);
  const behind = new THREE.Mesh(new THREE.SphereGeometry(0.7, 32, 24), skinBehind);
  behind.position.set(0.9, 0.3, -1.2);
  const box = new THREE.Mesh(new THREE.BoxGeometry(0.5, 0.5, 0.5), new THREE.MeshStandardMaterial({ color: 0x3366cc }));
  box.position.set(-0.7, -0.3, 1.2);
  const floor = new THREE.Mesh(new THREE.PlaneGeometry(12, 12), new THREE.MeshStandardMaterial({ color: 0x999999 }));
  floor.rotation.x = -Math.PI / 2;
  floor.position.y = -1;
  for (const m of [front, behind, box]) m.castShadow = m.receiveShadow = true;
  floor.receiveShadow = true;
  const light = new THREE.DirectionalLight(0xffffff, 3);
  light.position.set(-3, 5, 4);
  light.castShadow = true;
  Object.assign(light.shadow.camera, { left: -4, right: 4, top: 4, bottom: -4, near: 0.5, far: 20 });
  scene.add(front, behind, box, floor, light, light.target, new THREE.AmbientLight(0xffffff, 0.2));
  return { scene, camera, light, skin, skinBehind, subsurface: [front, behind], ordinary: [box, floor], map };
}
