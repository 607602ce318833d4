// What bench/webgpu/run.js reports from a run's medians (bench/webgpu/page.js's rows, ms): each
// subsurface frame over its own renderer's plain frame from the same rounds (the node over a plain
// RenderPipeline frame on each backend, the WebGL pipeline over a plain composer frame; with a
// base, the same for its rows), and the node's extra time split by stage (the scene split, the
// compose with the node's CPU side, the blur). Rows a run left out give nothing.

const ratio = (a, b) => (a > 0 && b > 0 ? a / b : undefined);

/**
 * @param {Record<string, number>} m median ms by row
 * @returns {{ overOwnPlain: Record<string, number>, nodeStagesMs: Record<string, Record<string, number>>, isotropicOverOneKernel: Record<string, number> }}
 */
export function webgpuOverheads(m) {
  const overOwnPlain = {};
  const put = (into, name, value) => { if (value !== undefined) into[name] = value; };
  put(overOwnPlain, 'pipeline', ratio(m.composer, m.composerPlain));
  put(overOwnPlain, 'pipelineBase', ratio(m.composerBase, m.composerPlain));
  for (const backend of ['webgpu', 'webgl']) {
    put(overOwnPlain, backend, ratio(m[`${backend}Node`], m[`${backend}Plain`]));
    put(overOwnPlain, `${backend}Base`, ratio(m[`${backend}NodeBase`], m[`${backend}Plain`]));
    put(overOwnPlain, `${backend}Away`, ratio(m[`${backend}NodeAway`], m[`${backend}PlainAway`])); // nothing subsurface on the screen
    put(overOwnPlain, `${backend}AwayBase`, ratio(m[`${backend}NodeAwayBase`], m[`${backend}PlainAway`]));
  }
  const nodeStagesMs = {};
  for (const backend of ['webgpu', 'webgl']) {
    const [plain, split, noBlur, node] = ['Plain', 'Split', 'NoBlur', 'Node'].map((row) => m[`${backend}${row}`]);
    if ([plain, split, noBlur, node].some((t) => t === undefined)) continue;
    nodeStagesMs[backend] = { split: split - plain, compose: noBlur - split, blur: node - noBlur };
  }
  const isotropicOverOneKernel = {};
  put(isotropicOverOneKernel, 'composer', ratio(m.composerIsotropic, m.composer));
  put(isotropicOverOneKernel, 'webgpu', ratio(m.webgpuNodeIsotropic, m.webgpuNode));
  put(isotropicOverOneKernel, 'webgl', ratio(m.webglNodeIsotropic, m.webglNode));
  return { overOwnPlain, nodeStagesMs, isotropicOverOneKernel };
}
