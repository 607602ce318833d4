import { it, beforeAll, afterAll } from 'vitest';
import { openPage } from '../../harness/page.js';
let page;
beforeAll(async () => { page = await openPage('/test/pages/lab.html'); });
afterAll(async () => { console.log(page.problems); await page.close(); });
it('cost', async () => {
  const r = await page.evaluate(async (variants) => {
    const { SSS, createRenderer, createComposer, flatScene } = window.lab;
    const width = 640, height = 360;
    const renderer = createRenderer(width, height);
    const gl = renderer.getContext();
    const built = flatScene({ width, height, pxPerMm: 3, pattern: 'cosines', frequencies: [0.3], phases: [0] });
    const sss = new SSS.SubsurfaceScattering({ scene: built.scene, camera: built.camera, worldUnitInMm: 1 });
    sss.makeSubsurface(built.material, { widthMm: 1 });
    const composer = createComposer(renderer);
    composer.addPass(sss);
    const pixel = new Uint8Array(4);
    const times = Object.fromEntries(variants.map((v) => [JSON.stringify(v), []]));
    const fence = () => { gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel); };
    const stageTimes = {};
    const blurOnly = () => { sss.blur.render(renderer, built.camera, (stage, draw) => { const t = performance.now(); draw(); renderer.setRenderTarget(stage === 'blurH' ? null : null); fence(); (stageTimes[stage] ??= []).push(performance.now() - t); }, sss.plan, sss.scenePass.subsurfaceBox); };
    for (let round = 0; round < 5; round++) {
      for (const v of variants) {
        Object.assign(sss, v);
        composer.render();
        const t0 = performance.now();
        for (let k = 0; k < 3; k++) blurOnly();
        times[JSON.stringify(v)].push((performance.now() - t0) / 3);
        const h = stageTimes.blurH.splice(0), vv = stageTimes.blurV.splice(0);
        (times[JSON.stringify(v) + ' H'] ??= []).push(h.reduce((a, b) => a + b) / h.length);
        (times[JSON.stringify(v) + ' V'] ??= []).push(vv.reduce((a, b) => a + b) / vv.length);
      }
    }
    return { times, plan: sss.plan.groups };
  }, JSON.parse(process.env.COST_V ?? '[{"kernelGroups":1},{"kernelGroups":"auto"}]'));
  for (const [k, t] of Object.entries(r.times)) console.log(k, t.map((x) => x.toFixed(1)).join(' '), 'median', t.sort((a, b) => a - b)[2].toFixed(1));
  console.log('groups', r.plan);
});
