// A small plant beside the head: five leaves up a stem (single planes, both sides drawn, cut out by an
// alpha test) swaying in the wind through an onBeforeCompile of the kind three.js users write
// (demo/sway.vert.glsl after three's begin_vertex, a `windTime` uniform the page moves). Made
// subsurface while shown (demo/appliers.js): lit from behind the leaves glow (a sheet of no
// thickness lets through the light that enters it, coloured by the leaf), and the light's depth
// pass runs the same hook, so the glow follows the sway. Hidden by default (the `foliage` key).
import {
  CylinderGeometry, DataTexture, DoubleSide, Group, Mesh, MeshStandardMaterial, PlaneGeometry, SRGBColorSpace,
} from 'three';
import swayGlsl from './sway.vert.glsl?raw';

/** The plant's place beside the head (right of it in the full-head shot; ~5 cm per unit: leaves 6 cm long). */
export const FOLIAGE_CENTRE = Object.freeze([3.0, 1.5, 2.2]);

/** A leaf's colour and outline: green with a paler midrib, opaque inside a pointed oval (u: base to tip). */
function leafTexture(width = 64, height = 32) {
  const data = new Uint8Array(width * height * 4);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const u = (x + 0.5) / width;
      const v = Math.abs((y + 0.5) / height - 0.5) * 2; // 0 on the midrib, 1 at the edge
      const inside = v < Math.sin(Math.PI * u ** 0.8) * 0.95;
      const rib = v < 0.06;
      data.set(rib ? [150, 190, 90, 255] : [70, 135, 35, inside ? 255 : 0], (y * width + x) * 4);
      if (!inside) data[(y * width + x) * 4 + 3] = 0;
    }
  }
  const texture = new DataTexture(data, width, height);
  texture.colorSpace = SRGBColorSpace;
  texture.needsUpdate = true;
  return texture;
}

/**
 * @returns {{ piece: Group, material: MeshStandardMaterial, setTime(seconds: number): void }} the
 *   plant (hidden), its leaves' one material, and the wind's clock
 */
export function createFoliagePiece() {
  const wind = { value: 0 }; // one uniform object for every program the hook makes
  const material = new MeshStandardMaterial({ map: leafTexture(), alphaTest: 0.5, side: DoubleSide, roughness: 0.6 });
  material.name = 'leaf';
  material.onBeforeCompile = (shader) => {
    shader.uniforms.windTime = wind;
    shader.vertexShader = `uniform float windTime;\n${shader.vertexShader.replace('#include <begin_vertex>', `#include <begin_vertex>\n${swayGlsl}`)}`;
  };
  const piece = new Group();
  piece.name = 'foliage';
  piece.position.fromArray(FOLIAGE_CENTRE);
  const stem = new Mesh(new CylinderGeometry(0.025, 0.04, 2.2, 8).translate(0, 0.3, 0), new MeshStandardMaterial({ color: 0x4a3a22, roughness: 0.8 }));
  piece.add(stem);
  // The leaf from the stem (x = 0) to its tip (x = 1.2), its front face to the camera (+z); the
  // leaves alternate up the stem, turned a little apart, so that few lie behind another.
  const geometry = new PlaneGeometry(1.2, 0.6, 12, 4).translate(0.6, 0, 0);
  const leaves = [[-0.6, 0.25, 0.35], [-0.15, 2.85, -0.3], [0.3, 0.5, 0.25], [0.75, 2.6, -0.2], [1.2, 1.5, 0]]; // height, angle in the picture, turn about it
  for (const [y, angle, turn] of leaves) {
    const leaf = new Mesh(geometry, material);
    leaf.position.y = y;
    leaf.rotation.set(turn, 0, angle, 'ZXY');
    leaf.castShadow = true;
    piece.add(leaf);
  }
  piece.visible = false;
  return { piece, material, setTime(seconds) { wind.value = seconds; } };
}
