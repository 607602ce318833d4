// The browser side of test/browser/integrations/postprocessing.test.js: pmndrs `postprocessing` (the real
// package), the pass of three-separable-sss/postprocessing, the demo's head and the lab's helpers
// on `window.pp`. Nothing here is part of the library.
import * as POSTPROCESSING from 'postprocessing';
import { TexturePass } from 'three/addons/postprocessing/TexturePass.js';
import { NoBlending } from 'three';
import { SubsurfaceScatteringPass } from 'three-separable-sss/postprocessing';
import { HEAD_WORLD_UNIT_IN_MM } from '/demo/headScene.js';
import { headRig } from './headRig.js';
import '/test/pages/lab.js';

/** Copies `texture` into `target` exactly (three's TexturePass, unblended). */
function copyTexture(renderer, texture, target) {
  const pass = new TexturePass(texture);
  pass.material.blending = NoBlending;
  pass.render(renderer, null, target);
  pass.dispose();
}

window.pp = { POSTPROCESSING, SubsurfaceScatteringPass, headRig, copyTexture, HEAD_WORLD_UNIT_IN_MM };
window.testReady = true;
