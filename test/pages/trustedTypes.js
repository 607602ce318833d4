// The library imported and rendering (transmittance, both blurs, the compose) on a page that
// enforces Trusted Types (trustedTypes.html). test/packaging/security.test.js collects the page's
// securitypolicyviolation events from before it loads; this module reports the frame, and then
// proves the enforcement is on (a string to innerHTML and to new Function must throw).
import * as THREE from 'three';
import { EffectComposer } from 'three/addons/postprocessing/EffectComposer.js';
import * as SSS from '/test/harness/sss.js';
import { readRenderTargetFloats } from '/dev/readback.js';
import { createFixture } from '/test/reliability/fixture.js';

async function run() {
  const renderer = new THREE.WebGLRenderer({ antialias: false });
  renderer.setPixelRatio(1);
  renderer.setSize(64, 36, false);
  document.body.appendChild(renderer.domElement);
  const t = createFixture(THREE, SSS, { renderer, EffectComposer, read: readRenderTargetFloats, width: 64, height: 36 });
  t.sss.debugView = 'final';
  const frame = await t.frame();
  const glError = renderer.getContext().getError();
  const violationsWhileRendering = window.__violations?.length ?? null;
  t.dispose();
  renderer.dispose();
  // The controls: with Trusted Types on, both must throw (and each reports a violation).
  const refused = [];
  try { document.createElement('div').innerHTML = '<b>x</b>'; } catch (e) { refused.push(`innerHTML: ${e.name}`); }
  // eslint-disable-next-line no-new-func
  try { new Function('return 1')(); } catch (e) { refused.push(`new Function: ${e.name}`); }
  return { ...frame, glError, violationsWhileRendering, refused, problems: t.sss.problems };
}

window.testReady = run();
