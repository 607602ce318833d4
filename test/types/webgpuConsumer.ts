// The webgpu entry as a TypeScript user writes it (test/packaging/types.test.js compiles it, strict,
// beside the README's WebGPURenderer snippet).
import * as THREE from 'three';
import { subsurfaceMaterial } from 'three-separable-sss/webgpu';

// The node material takes the place of the material it is made from, where the mesh's type names
// that material (TypeScript infers a Mesh's material type from its constructor).
const face = new THREE.Mesh(new THREE.SphereGeometry(), new THREE.MeshStandardMaterial({ roughness: 0.5 }));
face.material = subsurfaceMaterial(face.material, { widthMm: 1 });
const ear = new THREE.Mesh(new THREE.SphereGeometry(), new THREE.MeshPhysicalMaterial({ sheen: 0.2 }));
ear.material = subsurfaceMaterial(ear.material, { translucency: 0.2 });

// Its settings are properties, beside the given material's own and the node material's.
const skin = subsurfaceMaterial(new THREE.MeshPhysicalMaterial());
skin.widthMm = 2;
skin.transmittance = false;
skin.translucency = 0.3;
const sheen: number = skin.sheen;
const isNode: boolean = skin.isNodeMaterial;

export { sheen, isNode };
