// The speed-accuracy chart, drawn by Chart.js in the bench's page and returned as a PNG data URL:
// error against time on log scales, one series per method and profile, the Pareto front as a
// staircase, the module's default setting ringed.
import Chart from 'chart.js/auto';

const STYLES = {
  'reference skin': { color: '#d62728', pointStyle: 'triangle' },
  'marginal skin': { color: '#1f77b4', pointStyle: 'circle' },
  'marginal skinBurley': { color: '#17becf', pointStyle: 'rect' },
  'footprint skin': { color: '#2ca02c', pointStyle: 'circle' },
  'footprint skinBurley': { color: '#bcbd22', pointStyle: 'rect' },
  'auto skin': { color: '#9467bd', pointStyle: 'rectRot' },
  'auto skinBurley': { color: '#e377c2', pointStyle: 'rectRot' },
  'dense skin': { color: '#7f7f7f', pointStyle: 'crossRot' },
  'dense skinBurley': { color: '#8c564b', pointStyle: 'crossRot' },
};

/** Fills the canvas white under the chart (PNG would be transparent). */
const background = {
  id: 'background',
  beforeDraw(chart) {
    const { ctx, width, height } = chart;
    ctx.save();
    ctx.fillStyle = '#ffffff';
    ctx.fillRect(0, 0, width, height);
    ctx.restore();
  },
};

/** Writes each point's `label` (tap count, coverage) beside it. */
const pointLabels = {
  id: 'pointLabels',
  afterDatasetsDraw(chart) {
    const { ctx } = chart;
    ctx.save();
    ctx.font = '11px sans-serif';
    ctx.fillStyle = '#333333';
    chart.data.datasets.forEach((dataset, i) => {
      if (dataset.labelPoints !== true) return;
      chart.getDatasetMeta(i).data.forEach((element, j) => {
        const label = dataset.data[j].label;
        if (label) ctx.fillText(label, element.x + 7, dataset.labelBelow ? element.y + 14 : element.y - 5);
      });
    });
    ctx.restore();
  },
};

/** Log-axis bounds at 1, 2 or 5 × 10^k just outside the data, so that the end ticks read well. */
function niceBounds(values) {
  const steps = (v) => {
    const decade = 10 ** Math.floor(Math.log10(v));
    return [1, 2, 5, 10].map((m) => m * decade);
  };
  const lo = Math.min(...values) * 0.9;
  const hi = Math.max(...values) * 1.1;
  return { min: Math.max(...steps(lo).filter((s) => s <= lo)), max: Math.min(...steps(hi).filter((s) => s >= hi)) };
}

/**
 * @param {object} options
 * @param {Array<{ series: string, x: number, y: number, label?: string }>} options.points
 * @param {Array<{ label: string, points: Array<{ x: number, y: number }> }>} options.fronts Pareto
 *   fronts, each fastest first
 * @param {{ x: number, y: number, label: string }} options.highlight the default setting
 * @param {string} options.title
 * @param {string} options.subtitle
 * @param {string} options.xTitle
 * @param {string} options.yTitle
 * @param {number} [options.width=1100] CSS pixels
 * @param {number} [options.height=720] CSS pixels
 * @param {number} [options.pixelRatio=2]
 * @returns {string} PNG data URL
 */
export function drawChart({ points, fronts, highlight, title, subtitle, xTitle, yTitle, width = 1100, height = 720, pixelRatio = 2 }) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  document.body.appendChild(canvas);
  const series = [...new Set(points.map((p) => p.series))];
  const datasets = series.map((name) => {
    const style = STYLES[name] ?? { color: '#000000', pointStyle: 'circle' };
    return {
      label: name,
      data: points.filter((p) => p.series === name),
      backgroundColor: style.color,
      borderColor: style.color,
      pointStyle: style.pointStyle,
      pointRadius: 6,
      showLine: false,
      labelPoints: true,
      labelBelow: name.startsWith('auto'), // auto sits on a fixed tap count: keep both labels readable
      order: 1,
    };
  });
  fronts.forEach((front, i) => datasets.unshift({
    label: front.label,
    data: front.points,
    borderColor: i === 0 ? '#000000' : '#888888',
    borderDash: i === 0 ? [6, 4] : [2, 3],
    borderWidth: 1.5,
    pointRadius: 0,
    showLine: true,
    stepped: 'before', // from each point right, then down to the next: the dominated region's edge
    order: 2,
  }));
  datasets.unshift({
    label: highlight.label,
    data: [highlight],
    backgroundColor: 'rgba(255, 200, 0, 0.55)',
    borderColor: '#000000',
    borderWidth: 2,
    pointStyle: 'circle',
    pointRadius: 15,
    showLine: false,
    order: 3, // a halo under the point it marks
  });
  const chart = new Chart(canvas, {
    type: 'scatter',
    data: { datasets },
    plugins: [background, pointLabels],
    options: {
      animation: false,
      responsive: false,
      devicePixelRatio: pixelRatio,
      scales: {
        // Margins around the data so that no point sits on the frame.
        x: { type: 'logarithmic', ...niceBounds(points.map((p) => p.x)), title: { display: true, text: xTitle } },
        y: { type: 'logarithmic', ...niceBounds(points.map((p) => p.y)), title: { display: true, text: yTitle } },
      },
      plugins: {
        title: { display: true, text: title, font: { size: 16 } },
        subtitle: { display: true, text: subtitle },
        legend: { position: 'right' },
      },
    },
  });
  const url = canvas.toDataURL('image/png');
  chart.destroy();
  canvas.remove();
  return url;
}
