// Placeholder replaced below once the bench produces data.
export function drawChart() { throw new Error('not yet'); }
