// docs/SURFACE-TRUTH.md from bench/results/surface-truth.json (bench/surfaceTruth/run.js): every
// number comes from the results.
import { deviceName } from '../analysis.js';

/** A markdown table. */
const table = (header, rows) => [header, header.map(() => '---'), ...rows].map((r) => `| ${r.join(' | ')} |`).join('\n');

const REGIONS = ['all', 'silhouettes', 'creases', 'ears', 'eyes', 'lips', 'rest'];
const number = (v) => (v == null || Number.isNaN(v) ? '—' : v.toFixed(3));
const CHECK_LABEL = {
  density: (c) => `*the truth at ${c.density}× the samples per area, against the truth*`,
  atlas: (c) => `*the truth from a ${c.atlasSize}² atlas, against the truth*`,
};
const settingLabel = (name) => (name === 'default' ? "**default** (footprint, samples 'auto')" : name);
const IDEAL_BLUR_LABEL = {
  seen: '*an ideal normalised screen blur: the light the camera sees, each Gaussian averaged over the surface it sees*',
  seenTrueArea: '*the same with the true area within reach (the unseen part filled with that average)*',
  seenOrLit: '*with the light\'s view too: the light the camera or the light sees, each Gaussian averaged over that surface*',
  seenOrLitTrueArea: '*the same with the true area within reach*',
};

/** The largest amount a convergence check moved the truth by, over the regions with pixels. */
const worstMove = (configuration) => Math.max(...configuration.convergence.flatMap((c) => REGIONS.map((r) => c.relative[r] ?? 0)));

/** One configuration's table: each setting's error by region, then the truth's convergence. */
function configurationTable(configuration, regions = REGIONS) {
  const { cost } = configuration;
  const costOf = (name) => (cost ? [cost[name] == null ? '—' : cost[name].toFixed(1)] : []);
  const rows = configuration.settings.filter((s) => s.name !== 'none').map((s) => [settingLabel(s.name), ...regions.map((r) => number(s.relative[r])), ...costOf(s.name)]);
  for (const [name, blur] of Object.entries(configuration.idealBlurs ?? {})) rows.push([IDEAL_BLUR_LABEL[name], ...regions.map((r) => `*${number(blur.relative[r])}*`), ...(cost ? [''] : [])]);
  for (const check of configuration.convergence) rows.push([CHECK_LABEL[check.name](check), ...regions.map((r) => `*${number(check.relative[r])}*`), ...(cost ? [''] : [])]);
  const pixels = (r) => (r === 'all' ? configuration.pixels : configuration.regionPixels[r]);
  return table(['setting', ...regions.map((r) => `${r} (${pixels(r)} px)`), ...(cost ? ['SSS ms'] : [])], rows);
}

/** How the truth was made for one configuration, in a sentence (a truth kept from an earlier run of the same code says less). */
function truthSentence(c) {
  const parts = [];
  if (c.truthMs != null) {
    const reads = c.readShares ? ` (${Object.entries(c.readShares).map(([k, v]) => `${k} ${(100 * v).toFixed(1)} %`).join(', ')})` : '';
    const edge = c.lightEdgeMm != null ? ` on pieces of at most ${c.lightEdgeMm.toFixed(2)} mm` : '';
    parts.push(`Truth in ${(c.truthMs / 1000).toFixed(1)} s${c.cachedTruth ? ' (in an earlier run of the same code, kept)' : ''} from ${c.lightReads.toLocaleString('en')} light reads${edge}${reads}`);
  }
  if (c.localShare) parts.push(`Gaussians kept local at ${c.localShare.map((v) => `${(100 * v).toFixed(0)} %`).join(', ')} of the pixels (narrowest first)`);
  parts.push(`truth over unscattered light, R G B: ${c.truthOverUnscattered.map((v) => v.toFixed(4)).join(', ')}`);
  if (!c.convergence.length) parts.push('its convergence checks not run for this view (time on a shared machine); see the other views');
  return `${parts.join('; ')}.`;
}

/**
 * The short form for docs/BENCH.md: the default, the dense reference and the reference kernel per
 * view and light, over all pixels and the regions where screen space fails, beside the ideal
 * normalised screen blur (and the ideal blur of the camera's and the light's views with the true
 * area) and the truth's convergence (the most either check moved it).
 * @param {object} results bench/results/surface-truth.json
 */
export function surfaceTruthSummary(results) {
  const regions = ['all', 'silhouettes', 'creases', 'rest'];
  const rows = results.views.flatMap((c) => [
    ...['default', 'dense', 'reference17'].map((name) => c.settings.find((s) => s.name === name)).filter(Boolean)
      .map((s) => [c.name, s.name, ...regions.map((r) => number(s.relative[r]))]),
    ...(c.idealBlurs ? [
      [c.name, '*an ideal normalised screen blur*', ...regions.map((r) => `*${number(c.idealBlurs.seen.relative[r])}*`)],
      ...(c.idealBlurs.seenOrLitTrueArea ? [[c.name, '*an ideal blur of the camera\'s and the light\'s views, with the true area*', ...regions.map((r) => `*${number(c.idealBlurs.seenOrLitTrueArea.relative[r])}*`)]] : []),
    ] : []),
    ...(c.convergence.length ? [[c.name, '*the truth\'s own convergence (most moved)*', ...regions.map((r) => `*${number(Math.max(...c.convergence.map((k) => k.relative[r] ?? 0)))}*`)]] : []),
  ]);
  return table(['view, light', 'setting', ...regions], rows);
}

/** The goals, per configuration: what the default meets. */
function goalsTable(results) {
  const rows = results.views.map((c) => {
    const by = Object.fromEntries(c.settings.map((s) => [s.name, s.relative]));
    const d = by.default;
    const present = REGIONS.filter((r) => d[r] != null);
    const worst = present.reduce((a, r) => (d[r] > d[a] ? r : a), present[0]);
    const noT = by['default, no transmittance'];
    const worse = noT ? present.filter((r) => d[r] > noT[r] + 1e-3) : [];
    const bias = Object.fromEntries(c.settings.map((x) => [x.name, x.bias?.creases]));
    const red = (name) => (bias[name] ? `${(100 * bias[name][0]).toFixed(1)} %` : '—');
    return [c.name, `${number(d[worst])} (${worst})`, number(d.all), by.dense ? number(by.dense.all) : '—', c.idealBlurs ? number(c.idealBlurs.seen.relative.all) : '—',
      noT ? (worse.length ? `worse in ${worse.map((r) => `${r} ${number(noT[r])} → ${number(d[r])}`).join(', ')}` : 'never worse') : '—',
      `${red('none')} → ${red('default')}`];
  });
  return table(['view, light', 'default: worst region (goal ≤ 1.0)', 'default: all pixels (goal front ≤ 0.35)', 'dense: all pixels', 'ideal normalised screen blur: all pixels', 'transmittance (default against default without it)',
    'creases: red against the truth\'s, no scattering → default'], rows);
}

/** Per configuration: the default beside the ideal blurs, over all pixels, and the regions where the default is nearer the truth than the ideal screen blur or well farther. */
function idealBlursTable(results) {
  const rows = results.views.filter((c) => c.idealBlurs).map((c) => {
    const d = c.settings.find((x) => x.name === 'default').relative;
    const { seen, seenTrueArea, seenOrLit, seenOrLitTrueArea } = c.idealBlurs;
    const present = REGIONS.filter((r) => r !== 'all' && seen.relative[r] != null);
    const listed = (regions) => (regions.length ? regions.map((r) => `${r} ${number(d[r])} (${number(seen.relative[r])})`).join(', ') : 'none');
    return [c.name, number(d.all), number(seen.relative.all), number(seenTrueArea.relative.all), number(seenOrLit?.relative.all), number(seenOrLitTrueArea?.relative.all),
      listed(present.filter((r) => d[r] < seen.relative[r])), listed(present.filter((r) => d[r] > seen.relative[r] + 0.05))];
  });
  return table(['view, light', 'default: all pixels', 'ideal normalised screen blur', 'with the true area', 'with the light\'s view too', 'and the true area',
    'regions where the default is nearer the truth than the ideal screen blur (its value)', 'regions where it is 0.05 or more farther'], rows);
}

/**
 * @param {object} results bench/results/surface-truth.json
 * @returns {string} markdown
 */
export function surfaceTruthMarkdown(results) {
  const { view, plane } = results;
  const sections = results.views.map((c) => {
    const slug = c.name.replace(/[^a-z0-9]+/gi, '-');
    const by = Object.fromEntries(c.settings.map((s) => [s.name, s.relative]));
    return `## ${c.name[0].toUpperCase()}${c.name.slice(1)} (light azimuth ${c.lightAzimuthDeg}°, elevation ${c.lightElevationDeg}°)

${truthSentence(c)}

${configurationTable(c)}

The default misses ${number(by.default.all)} of the effect over all pixels, the dense screen-space reference ${number(by.dense?.all)}${c.convergence.length ? `; the truth's own convergence moved it by at most ${number(worstMove(c))} (goal ≤ 0.05)` : ''}.

| truth | default | unscattered |
|---|---|---|
| ![truth](surface-truth/image-${slug}-truth.png) | ![default](surface-truth/image-${slug}-setting.png) | ![unscattered](surface-truth/image-${slug}-unscattered.png) |

Heat maps of |setting − truth| (sum of RGB; white at 0.05): ![default](surface-truth/heat-${slug}-default.png) ![dense](surface-truth/heat-${slug}-dense.png)
`;
  });
  const planeBy = Object.fromEntries(plane.settings.map((s) => [s.name, s.relative]));
  return `# Against a surface-space truth

Generated by \`npm run bench:truth\` (bench/surfaceTruth/run.js) on ${deviceName(results.webgl)}, ${results.date.slice(0, 10)}, in ${results.seconds.toFixed(0)} s.

The screen-space methods see only the pixels the camera sees. The truth here does not, and it
scatters the light the pipeline blurs (bench/surfaceTruth/page.js):

- **Its light.** Where the camera sees the surface, the camera pixels' own diffuse light: the
  pipeline's diffuse attachment of the same frame, at the same ${view.width}×${view.height}, float targets. Only
  where the camera does not see it (behind silhouettes, inside folds, the back of the head), the
  same material's light rendered into the head's UV atlas (bench/surfaceTruth/atlas.js). A surface
  point is the camera's when it projects onto a subsurface pixel whose surface lies at its distance
  within 0.5 mm plus that pixel's own depth span. The pipeline's transmittance is left out of this
  light: the truth makes its own (light entering the far side of an ear reaches the near side
  through it), so a method's transmittance is measured against it, not built into it.
- **Its samples.** The mesh's own triangles, each split at its edges' midpoints into four
  congruent pieces of exactly a quarter of its area, recursively (bench/surfaceTruth/scatter.js):
  the pieces' areas sum to the mesh's, so nothing is renormalised. Each of d'Eon's six Gaussians of
  the skin profile (widthMm ${view.widthMm}) is summed over pieces no longer than its σ, each carrying the mean
  light of its sub-pieces; one narrower than a quarter of a pixel's footprint is kept local (the
  light is one value across the pixel).
- **Its distance.** R(r) at the straight 3D distance, through the material: the dipole's BSSRDF
  is a function of |x − y| (Jensen et al. 2001); on the head's gentle curves it equals the
  distance along the surface within (σ/ρ)², and through an ear's rim or a lip light does cross the
  tissue. (Across the air of an eyelid slit it overestimates.)

Unit tests (test/node/bench/surfaceTruth.test.js, Node): the pieces' areas sum to the mesh's within
1e-9; a step of light on an irregularly triangulated plane is within 2e-3 of the closed form
(erfc per Gaussian); uniform light on a sphere keeps Σ wᵢ (1 − exp(−2ρ²/vᵢ)), the closed form at
3D distances, within 5e-4; the ideal blurs below average only the light seen (a plane lit where
the camera does not see, with a ramp where it does; a sphere whose far half it does not see) within
1e-3 of their closed forms.

Error: ‖setting − truth‖ / ‖no scattering − truth‖ over each region's pixels (RGB), i.e. the part of
the effect a setting misses: 0 is the truth, 1 no better than no scattering ("no scattering": no
blur and no transmittance, the light the truth scatters). Regions (bench/surfaceTruth/regions.js):
silhouettes (surface within 2 px of a non-subsurface pixel or seen at a cosine below 0.3), creases
(a valley in the view's depth: farther than the pixels 2 px away on both sides by 0.5 mm, along x
or y: eyelid slits, the lip line, nostrils, ear folds), ears, eyes and lips (boxes on the scan), the
rest. SSS ms: the blur's (or the dense pass's) time from timer queries, CPU time on SwiftShader on
a shared machine, the median of interleaved rounds in the same page (front light only): compare
within a table, not across runs. Beside every table, in italics, the truth's convergence: the truth at twice the samples per
area, and from an atlas of twice the side, against the truth, in the same measure (goal ≤ 0.05).

## A flat plane: the truth against the exact convolution

The bench's slab (bench/scenes.js) at ${plane.view.width}×${plane.view.height}: a plane facing the camera, a hard-edged disc of light on it.
There the truth is the exact convolution of the pixels' light, which the dense screen-space
reference computes too (pixel-exact energies): the dense reference misses ${number(planeBy.dense?.all)} of
the effect (goal ≤ 0.05), the default ${number(planeBy.default?.all)}. (Its "silhouettes" are the image's
border, where no screen-space method sees the light beyond the frame; "ears" a patch of the plane
inside the head's ear boxes.)

${truthSentence(plane)}

${configurationTable(plane, ['all', 'silhouettes', 'rest'])}

## Goals

Per view and light, what the default meets: no region worse than no scattering (≤ 1.0) and,
front-lit, at most 0.35 of the effect missed over all pixels. The last column is the mean of
(setting − truth) over the mean truth in the crease pixels, red channel: negative is darker in
red than the truth.

${goalsTable(results)}

## Ideal blurs of what is seen

The truth's pass also computes ideal blurs of what a view sees (bench/surfaceTruth/scatter.js's
idealBlursOf). The first is an ideal normalised screen blur: the light the camera sees, each
Gaussian averaged over the surface the camera sees, at the true 3D distances and areas. It has
an exact kernel and a perfect depth rule, and like every screen blur its kernel sums to 1 over
the surface it keeps. Where light comes from surface the camera cannot see (behind a silhouette,
inside a fold, lit from behind) it puts the average of what it sees instead. It is not a bound:
a real blur's own errors can land nearer the truth, and the default's does in some regions (the
table's second-to-last column).

A second line fills that unseen part with the same average but keeps the true area within reach:
more than a plane's in a fold, less round a convex edge. Two more lines add the surface the light
sees, found with the library's own light depth map at 2048²: the light's view, as a translucent
shadow map holds it (Dachsbacher and Stamminger 2003). The last of them also knows the area of
surface neither view sees, which no shadow map has, and fills it with the average of what is
seen. In the tables above all four are the italic rows below the settings.

${idealBlursTable(results)}

Where even the blurs that see more stay far from the truth, the missing light is neither in the
camera's nor the light's view; where the light's view brings a blur near the truth, gathering that
view is where to look.

${sections.join('\n')}
What no screen-space method can see: light entering surfaces hidden from the camera (behind a
silhouette, inside an ear fold) and the true surface area of walls seen edge-on (eyelid slits,
nostrils); "Ideal blurs of what is seen" above measures both.
`;
}
