// docs/transfer.svg from bench/results/transfer.json: one panel per profile, transfer against
// frequency (cycles/mm, log scale), the analytic curves per channel as lines, the measured
// transfers as markers, one marker shape per scale (px/mm). Plain SVG text: no browser needed.
import { transferOf } from '../../test/oracle/closedForms.js';

const CHANNELS = [['R', '#d62728'], ['G', '#2ca02c'], ['B', '#1f77b4']];
const MARKERS = ['circle', 'square', 'diamond', 'triangle'];
const PANEL = { width: 420, height: 300, left: 52, right: 16, top: 34, bottom: 44 };
const F_RANGE = [0.04, 2]; // cycles/mm

function marker(shape, x, y, colour) {
  const r = 4;
  const style = `fill="none" stroke="${colour}" stroke-width="1.4"`;
  if (shape === 'circle') return `<circle cx="${x}" cy="${y}" r="${r}" ${style}/>`;
  if (shape === 'square') return `<rect x="${x - r}" y="${y - r}" width="${2 * r}" height="${2 * r}" ${style}/>`;
  if (shape === 'diamond') return `<path d="M${x} ${y - r - 1}L${x + r + 1} ${y}L${x} ${y + r + 1}L${x - r - 1} ${y}Z" ${style}/>`;
  return `<path d="M${x} ${y - r - 1}L${x + r + 1} ${y + r}L${x - r - 1} ${y + r}Z" ${style}/>`;
}

function panel(profile, rows, offsetX) {
  const w = PANEL.width - PANEL.left - PANEL.right;
  const h = PANEL.height - PANEL.top - PANEL.bottom;
  const [f0, f1] = F_RANGE.map(Math.log10);
  const X = (f) => offsetX + PANEL.left + ((Math.log10(f) - f0) / (f1 - f0)) * w;
  const Y = (t) => PANEL.top + (1 - t) * h;
  const parts = [`<text x="${offsetX + PANEL.left + w / 2}" y="20" text-anchor="middle" font-weight="bold">${profile}</text>`,
    `<rect x="${X(F_RANGE[0])}" y="${Y(1)}" width="${w}" height="${h}" fill="none" stroke="#999"/>`];
  for (const t of [0, 0.25, 0.5, 0.75, 1]) {
    parts.push(`<line x1="${X(F_RANGE[0])}" x2="${X(F_RANGE[1])}" y1="${Y(t)}" y2="${Y(t)}" stroke="#eee"/>`,
      `<text x="${X(F_RANGE[0]) - 6}" y="${Y(t) + 4}" text-anchor="end">${t}</text>`);
  }
  for (const f of [0.05, 0.1, 0.2, 0.5, 1, 2]) {
    parts.push(`<line x1="${X(f)}" x2="${X(f)}" y1="${Y(0)}" y2="${Y(1)}" stroke="#eee"/>`, `<text x="${X(f)}" y="${Y(0) + 16}" text-anchor="middle">${f}</text>`);
  }
  parts.push(`<text x="${offsetX + PANEL.left + w / 2}" y="${PANEL.height - 8}" text-anchor="middle">cycles/mm</text>`);
  const samples = Array.from({ length: 80 }, (_, i) => 10 ** (f0 + ((f1 - f0) * i) / 79));
  CHANNELS.forEach(([, colour], c) => {
    parts.push(`<polyline fill="none" stroke="${colour}" stroke-width="1.5" points="${samples.map((f) => `${X(f).toFixed(1)},${Y(transferOf(profile, f)[c]).toFixed(1)}`).join(' ')}"/>`);
    rows.forEach((row, k) => row.frequencies.forEach((f, j) => parts.push(marker(MARKERS[k % MARKERS.length], X(f), Y(row.measured[c][j]), colour))));
  });
  return parts.join('\n');
}

/**
 * @param {{ measurements: { profile: string, pxPerMm: number, frequencies: number[], measured: number[][], worst: number }[], setting: string }} results
 * @returns {string} SVG text
 */
export function transferSvg(results) {
  const profiles = [...new Set(results.measurements.map((m) => m.profile))];
  const scales = [...new Set(results.measurements.map((m) => m.pxPerMm))];
  const width = PANEL.width * profiles.length;
  const legendY = PANEL.height + 8;
  const legend = [
    ...CHANNELS.map(([name, colour], c) => `<line x1="${20 + 90 * c}" x2="${44 + 90 * c}" y1="${legendY}" y2="${legendY}" stroke="${colour}" stroke-width="2"/><text x="${50 + 90 * c}" y="${legendY + 4}">${name} analytic</text>`),
    ...scales.map((s, k) => `${marker(MARKERS[k % MARKERS.length], 290 + 125 * k, legendY, '#333')}<text x="${300 + 125 * k}" y="${legendY + 4}">measured, ${s} px/mm</text>`),
  ];
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${PANEL.height + 44}" font-family="sans-serif" font-size="11">
<rect width="100%" height="100%" fill="#fff"/>
${profiles.map((p, i) => panel(p, results.measurements.filter((m) => m.profile === p), i * PANEL.width)).join('\n')}
${legend.join('\n')}
<text x="20" y="${legendY + 26}" fill="#666">${results.setting}; worst |measured − analytic| ${Math.max(...results.measurements.map((m) => m.worst)).toFixed(3)}</text>
</svg>
`;
}
