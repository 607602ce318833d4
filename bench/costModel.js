// The bench's cost model (issue 19): what each stage of a frame writes and reads per screen pixel,
// and the memory of the pipeline's targets, from the attachment formats
// (src/2-scene-split/subsurfaceTarget.js, src/3-blur/BlurStage.js), the passes and their taps
// (shaders/3-blur/blurTaps.glsl). SwiftShader times are CPU times; a GPU is mostly
// bound by memory traffic, which this counts instead.
//
// Cache assumption ("compulsory traffic"): every texel a pass reads comes from memory once per pass
// and stays in cache for the neighbouring pixels' taps (a vertical pass at 1920×1080 with a reach of
// 30 rows keeps 30 × 1920 × 16 B ≈ 0.9 MB of diffuse + surface live: an L2 holds it); the small
// tables (footprints, profile: a few KB) cost nothing; every write goes to memory; clears are
// counted as writes (a GPU's fast clear may make them nearly free). The texel fetches (what the
// texture units do, the L1 traffic) are counted apart, with no reuse. Material textures are not
// counted: a plain frame reads the same.
// No imports: it loads in Node (the runner, the unit test) and in the page alike.

/** Bytes per texel of the formats the pipeline's targets use. */
export const TEXEL_BYTES = Object.freeze({ rgba16f: 8, rgba32f: 16, rg32f: 8, depth24: 4, rgba32ui: 16 });

/** The pipeline's targets (the composer's own buffers are the application's, as with a RenderPass). */
export const TARGETS = Object.freeze([
  { name: 'colour (multi-target 0)', format: 'rgba16f', multisampled: true },
  // RGBA32F while it carries the depth (SubsurfaceScenePass.diffuseCarriesDepth: without MSAA only).
  { name: 'diffuse (multi-target 1)', format: 'rgba16f', carriedFormat: 'rgba32f', multisampled: true, carriedWithMsaa: false },
  { name: 'surface (multi-target 2)', format: 'rg32f', multisampled: true },
  { name: 'depth (multi-target)', format: 'depth24', multisampled: true },
  // RGBA32F: it carries the depth to the vertical pass.
  { name: 'horizontal blur', format: 'rgba16f', carriedFormat: 'rgba32f', multisampled: false },
  { name: 'horizontal blur, isotropic groups (two attachments; built when groups are possible)', format: 'rgba32ui', attachments: 2, multisampled: false, groups: true },
  { name: 'scattered light', format: 'rgba16f', multisampled: false },
]);

/**
 * The memory of the pipeline's targets at `width` × `height`: with MSAA (`samples` > 0) three keeps
 * a multisampled renderbuffer per multi-target attachment besides the resolved texture.
 * @returns {{ targets: Array<{ name: string, bytes: number }>, bytes: number }}
 */
export function targetMemory(width, height, { samples = 0, groups = true, carriesDepth = true } = {}) {
  const pixels = width * height;
  const formatOf = (t) => (carriesDepth && t.carriedFormat && !(samples > 0 && t.carriedWithMsaa === false) ? t.carriedFormat : t.format);
  const targets = TARGETS.filter((t) => groups || !t.groups)
    .map((t) => ({ name: t.name, bytes: pixels * TEXEL_BYTES[formatOf(t)] * (t.attachments ?? 1) * (1 + (t.multisampled && samples > 0 ? samples : 0)) }));
  return { targets, bytes: targets.reduce((sum, t) => sum + t.bytes, 0) };
}

/**
 * The switches the traffic depends on: version 0.2's frame (`BEFORE`) and this one's (`AFTER`).
 * depthPrepass: the scene split's first call draws the subsurface materials' depth;
 * confineToSubsurface: the blur passes are scissored to the subsurface pixels' screen box;
 * fetchesEverywhere: the compose reads the scattered light and the surface at every pixel;
 * skipsEmptyTexels: a tap on a texel centre fetches one texel, not two (fetches only: its
 * neighbours' taps read the other texel anyway, so the memory traffic is the same);
 * lightCarriesDepth: the horizontal pass writes its light with the depth in the alpha (RGBA32F,
 * 16 B, instead of RGBA16F), so a vertical tap fetches one texel of 16 B instead of light and
 * surface (8 + 8; the same bytes read, half the fetches; one kernel only);
 * diffuseCarriesDepth: the diffuse attachment does so too (RGBA32F; without MSAA), so a
 * horizontal tap fetches one texel; the split writes and clears 8 B more per pixel, and a compose
 * that reads the mask from it reads 16 B (both modelled for the head's frame: one profile, the
 * depth rule on; several profiles still fetch the surface per tap for the slot);
 * composeMaskFromScattered: the compose reads the mask from the scattered light (8 B) inside the
 * box only, instead of the diffuse attachment at every pixel and the scattered light on the mask;
 * kernelGroups: the isotropic blur's groups (issue 20; 1: one kernel): with more, the horizontal
 * pass writes two RGBA32UI texels (32 B) instead of one RGBA16F (8 B), the vertical pass reads
 * them (and fetches both per tap, an upper bound: past groups 1 and 2's reach it fetches one), and
 * both passes fetch the group fractions per footprint (a small table: free in memory traffic);
 * groupsCarryDepth: the groups' alphas carry the depth (without MSAA), so a vertical tap of the
 * groups reads no surface.
 */
export const BEFORE = Object.freeze({ depthPrepass: true, confineToSubsurface: false, fetchesEverywhere: false, skipsEmptyTexels: false, lightCarriesDepth: false, diffuseCarriesDepth: false, composeMaskFromScattered: false, kernelGroups: 1 });
export const AFTER = Object.freeze({ depthPrepass: false, confineToSubsurface: true, fetchesEverywhere: false, skipsEmptyTexels: true, lightCarriesDepth: true, diffuseCarriesDepth: true, composeMaskFromScattered: true, kernelGroups: 1 });
/** This version with the isotropic blur (`kernelGroups: 'auto'`, four groups near): what the groups add, modelled. */
export const ISOTROPIC = Object.freeze({ ...AFTER, kernelGroups: 4, groupsCarryDepth: true });

/**
 * Directions the issue names that are not built, modelled on top of AFTER (what they would save,
 * not a measurement): surfaceFromDepth, no surface attachment (the blur reads the depth texture,
 * 4 B, and the width from a channel elsewhere: the diffuse alpha now carries the depth); composeInBlur, the compose folded into the vertical
 * pass (no scattered target; that pass then covers the whole frame and writes the output).
 */
export const NOT_BUILT = Object.freeze({
  surfaceFromDepth: Object.freeze({ ...AFTER, surfaceFromDepth: true }),
  composeInBlur: Object.freeze({ ...AFTER, composeInBlur: true }),
  both: Object.freeze({ ...AFTER, surfaceFromDepth: true, composeInBlur: true }),
});

const { rgba16f: RGBA16F, rg32f: RG32F, depth24: DEPTH } = TEXEL_BYTES;

/**
 * One stage's traffic per screen pixel: bytes written, read from memory, and fetched by the
 * texture units, and `fetches`, the texel fetch instructions (the small tables' included).
 */
const stage = (written, read, fetched = read, fetches = 0) => ({ written, read, fetched, fetches });

/**
 * A blur pass over `area` of the frame, `subsurface` of it on the mask, `taps` per direction,
 * reading `surface` bytes per texel for the surface (the attachment, or the depth texture).
 */
function blurPass(area, subsurface, taps, surface, centred = 0, { input = RGBA16F, output = RGBA16F, carried = false, lightFetches = 1, grouped = false } = {}) {
  // Every pixel reads its centre (the light, surface) and writes its result; a mask pixel also
  // reads its two neighbours' surface (the slope) and, per tap, two texels of light and surface
  // (one for the `centred` taps on a texel centre). `input`, `output`: bytes per texel of the light
  // read and written (the isotropic groups between the passes: 32); `carried`: the light holds the
  // depth, so a tap reads no surface; `lightFetches`: fetch instructions per light texel (the
  // isotropic groups' two attachments: 2); `grouped`: the isotropic blur's passes also fetch the
  // group fractions, for the centre, the near count and each footprint (a small table: no bytes).
  // `taps` counts the centre: (taps − 1) / 2 footprints a side, each one tap between two texels.
  const centre = input + surface;
  const texels = 2 * (taps - 1) - centred;
  const perMaskPixel = 2 * surface + texels * (input + (carried ? 0 : surface));
  // Fetch instructions: the centre's light and surface, the slope's two, each tap texel's light and surface, and the
  // footprint loop's tables: the centre's energy (two profile texels), then per footprint its
  // table texel and two profile texels, but the last (the tail takes the energy left): 3 (taps − 1) / 2.
  const tables = 3 * (taps - 1) / 2 + (grouped ? 2 + (taps - 1) / 2 : 0);
  const fetches = area * (lightFetches + 1) + subsurface * (2 + texels * (lightFetches + (carried ? 0 : 1)) + tables);
  return stage(area * output, area * centre, area * centre + subsurface * perMaskPixel, fetches);
}

/**
 * Bytes per screen pixel of each stage (and of a plain three.js frame of the same scene).
 * @param {{ depthPrepass: boolean, confineToSubsurface: boolean, fetchesEverywhere: boolean, skipsEmptyTexels?: boolean }} switches BEFORE, AFTER or between
 * @param {object} scene what the frame covers, as fractions of its pixels
 * @param {number} scene.subsurface pixels on subsurface objects (the mask)
 * @param {number} scene.box pixels in the subsurface pixels' screen box
 * @param {number} [scene.ordinary=0] pixels on ordinary opaque objects
 * @param {number} scene.taps taps per pixel and direction on the mask (samples 'auto': the mean)
 * @param {number} [scene.centred=0] of them, taps on a texel centre (footprints one pixel wide)
 * @returns {{ scene: object, blurH: object, blurV: object, compose: object, total: object, plain: object }}
 *   each { written, read, fetched } bytes per pixel
 */
export function frameTraffic(switches, { subsurface, box, ordinary = 0, taps, centred = 0 }) {
  const s = subsurface;
  const covered = s + ordinary;
  // Scene split: the four attachments cleared; the first call's ordinary fragments (depth test and
  // write, colour); the prepass's depth; the split's fragments (depth, three attachments).
  const prepass = switches.depthPrepass ? s : 0;
  const surfaceAttachment = switches.surfaceFromDepth ? 0 : RG32F;
  const diffuse = switches.diffuseCarriesDepth ? TEXEL_BYTES.rgba32f : RGBA16F;
  const attachments = RGBA16F + diffuse + surfaceAttachment + DEPTH; // colour, diffuse, surface, depth
  const scene = stage(attachments + ordinary * (DEPTH + RGBA16F) + prepass * DEPTH + s * (DEPTH + RGBA16F + diffuse + surfaceAttachment),
    ordinary * DEPTH + prepass * DEPTH + s * DEPTH);
  const area = switches.confineToSubsurface ? box : 1;
  const surface = switches.surfaceFromDepth ? DEPTH : RG32F;
  const skipped = switches.skipsEmptyTexels ? centred : 0;
  const grouped = (switches.kernelGroups ?? 1) > 1;
  // The depth between the passes: in the light (one kernel), in the groups' alphas (groupsCarryDepth).
  const carried = grouped ? switches.groupsCarryDepth === true : switches.lightCarriesDepth === true;
  const between = grouped ? 2 * TEXEL_BYTES.rgba32ui : carried ? TEXEL_BYTES.rgba32f : RGBA16F; // the light between the passes
  const blurH = blurPass(area, s, taps, surface, skipped, { input: diffuse, output: between, carried: switches.diffuseCarriesDepth === true, grouped });
  // Compose: depth and colour at every pixel; the scattered light (its alpha the mask) in the box
  // (composeMaskFromScattered), or the diffuse (its mask) at every pixel and the scattered light on
  // the mask, or everything everywhere with the surface (as before issue 10); out: colour and depth.
  const everywhere = switches.fetchesEverywhere ? 1 : 0;
  const composeRead = DEPTH + RGBA16F + (everywhere ? diffuse + RGBA16F + RG32F : switches.composeMaskFromScattered ? box * RGBA16F : diffuse + s * RGBA16F);
  let blurV = blurPass(area, s, taps, surface, skipped, { input: between, carried, lightFetches: grouped ? 2 : 1, grouped });
  const composeFetches = 2 + (everywhere ? 3 : switches.composeMaskFromScattered ? box : 1 + s);
  let compose = stage(RGBA16F + DEPTH, composeRead, composeRead, composeFetches);
  if (switches.composeInBlur) {
    // The vertical pass over the whole frame: its taps as before, plus colour and depth read and
    // the output (colour, depth) written at every pixel instead of the scattered light.
    const v = blurPass(1, s, taps, surface, skipped, { input: between, carried });
    blurV = stage(RGBA16F + DEPTH, v.read + RGBA16F + DEPTH, v.fetched + RGBA16F + DEPTH, v.fetches + 2); // (the mask from the light it reads)
    compose = stage(0, 0);
  }
  const stages = { scene, blurH, blurV, compose };
  const total = stage(...['written', 'read', 'fetched', 'fetches'].map((k) => Object.values(stages).reduce((sum, x) => sum + x[k], 0)));
  // A plain frame: colour and depth cleared, then each covered pixel's fragment (depth, colour).
  const plain = stage(RGBA16F + DEPTH + covered * (DEPTH + RGBA16F), covered * DEPTH);
  return { ...stages, total, plain };
}
