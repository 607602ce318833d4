// Plots the blur kernel (weight per RGB channel against offset in mm) on a small 2D canvas, and,
// for the profile-based methods, the profile's marginal a(x) it approximates.

/**
 * @param {HTMLCanvasElement} canvas
 * @param {Float32Array} kernel (weight R, G, B, offset mm) per tap
 * @param {object|null} profile with marginal(xMm) → [r, g, b], or null
 */
export function drawKernel(canvas, kernel, profile) {
  const ctx = canvas.getContext('2d');
  const { width, height } = canvas;
  ctx.clearRect(0, 0, width, height);
  ctx.fillStyle = '#000a';
  ctx.fillRect(0, 0, width, height);
  const taps = kernel.length / 4;
  let radius = 0;
  let peak = 0;
  for (let i = 0; i < taps; i++) {
    radius = Math.max(radius, Math.abs(kernel[i * 4 + 3]));
    for (let c = 0; c < 3; c++) peak = Math.max(peak, kernel[i * 4 + c]);
  }
  radius = radius * 1.1 || 1;
  const x = (mm) => width / 2 + (mm / radius) * (width / 2 - 8);
  const y = (w) => height - 16 - (w / peak) * (height - 28);
  const colours = ['#ff5a4a', '#5adc6a', '#5a8cff'];
  ctx.lineWidth = 2;
  for (let c = 0; c < 3; c++) {
    ctx.strokeStyle = colours[c];
    for (let i = 0; i < taps; i++) {
      const px = x(kernel[i * 4 + 3]) + (c - 1) * 2;
      ctx.beginPath();
      ctx.moveTo(px, y(0));
      ctx.lineTo(px, y(kernel[i * 4 + c]));
      ctx.stroke();
    }
  }
  if (profile) {
    // The marginal density, scaled so its peak meets the tallest tap of that channel.
    const samples = 120;
    ctx.lineWidth = 1;
    for (let c = 0; c < 3; c++) {
      const values = Array.from({ length: samples + 1 }, (_, i) => profile.marginal(((i / samples) * 2 - 1) * radius)[c]);
      const max = Math.max(...values);
      let tap = 0;
      for (let i = 0; i < taps; i++) tap = Math.max(tap, kernel[i * 4 + c]);
      ctx.strokeStyle = colours[c];
      ctx.beginPath();
      values.forEach((v, i) => {
        const px = x(((i / samples) * 2 - 1) * radius);
        const py = y(max > 0 ? (v / max) * tap : 0);
        if (i === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      });
      ctx.stroke();
    }
  }
  ctx.fillStyle = '#ccc';
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillText(`kernel: ${taps} taps, ±${(radius / 1.1).toFixed(2)} mm`, 6, 12);
  ctx.fillText('offset (mm)', width - 70, height - 4);
}
