// The fresh app's scene, the same in both pages: a lit sphere (MeshStandardMaterial) and a
// SpotLight, 640×360, no animation loop (bench/footprint/run.js draws each frame itself).
import * as THREE from 'three';

export const WIDTH = 640;
export const HEIGHT = 360;

export function createScene() {
  const renderer = new THREE.WebGLRenderer();
  renderer.setPixelRatio(1);
  renderer.setSize(WIDTH, HEIGHT);
  document.body.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x202020);
  const camera = new THREE.PerspectiveCamera(30, WIDTH / HEIGHT, 0.01, 10);
  camera.position.set(0, 0, 0.5);

  const material = new THREE.MeshStandardMaterial({ color: 0xe0b8a0, roughness: 0.5 });
  const sphere = new THREE.Mesh(new THREE.SphereGeometry(0.08, 64, 32), material);
  scene.add(sphere);

  // From the side and a little behind: it lights the sphere's right half and shines through its
  // edge (so the pipeline's light depth pass runs: transmittance).
  const light = new THREE.SpotLight(0xffffff, 1.5, 0, Math.PI / 8, 0.3);
  light.position.set(0.45, 0.15, -0.25);
  scene.add(light, light.target, new THREE.HemisphereLight(0xffffff, 0x443333, 0.5));
  return { renderer, scene, camera, light, material };
}
