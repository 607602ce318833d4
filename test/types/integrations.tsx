// The subpath exports in a strict TypeScript consumer: pmndrs postprocessing and React Three Fiber
// (JSX), as the README shows them. Compiled by test/packaging/types.test.js; must have no error.
import * as THREE from 'three';
import { EffectComposer, EffectPass, BloomEffect, ToneMappingEffect } from 'postprocessing';
import { useState } from 'react';
import { Canvas } from '@react-three/fiber';
import { SubsurfaceScatteringPass } from 'three-separable-sss/postprocessing';
import { SubsurfaceComposer, Subsurface, useSubsurface, useSubsurfaceComposer, useSubsurfaceScattering } from 'three-separable-sss/react';

// pmndrs postprocessing: the pass in place of its RenderPass.
export function pmndrs(renderer: THREE.WebGLRenderer, scene: THREE.Scene, camera: THREE.PerspectiveCamera, light: THREE.SpotLight, skin: THREE.MeshStandardMaterial) {
  const composer = new EffectComposer(renderer, { frameBufferType: THREE.HalfFloatType });
  const sss = new SubsurfaceScatteringPass({ scene, camera, light, worldUnitInMm: 1000 });
  sss.makeSubsurface(skin, { widthMm: 1 });
  composer.addPass(sss);
  composer.addPass(new EffectPass(camera, new BloomEffect(), new ToneMappingEffect()));
  sss.pipeline.debugView = 'mask';
  sss.clear = false;
  return composer;
}

// React Three Fiber.
function Skin() {
  const [light, setLight] = useState<THREE.SpotLight | null>(null);
  return (
    <>
      <spotLight ref={setLight} position={[0.6, 0.4, -1]} intensity={30} />
      <SubsurfaceComposer light={light} worldUnitInMm={1000} profile="skin" samples="auto">
        <mesh>
          <torusKnotGeometry args={[0.08, 0.025, 200, 32]} />
          <meshStandardMaterial color="#e0b8a0">
            <Subsurface widthMm={1} />
          </meshStandardMaterial>
        </mesh>
        <Loaded material={new THREE.MeshPhysicalMaterial()} />
      </SubsurfaceComposer>
    </>
  );
}

function Loaded({ material }: { material: THREE.MeshStandardMaterial }) {
  useSubsurface(material, { widthMm: 2 });
  const { pass } = useSubsurfaceComposer();
  if (pass) pass.debugView = 'final';
  return null;
}

export function HookOnly() {
  const registry = useSubsurfaceScattering({ method: 'reference', antialias: 0 });
  if (registry.pass) registry.pass.split = 0.5;
  return null;
}

export const app = <Canvas><Skin /></Canvas>;
