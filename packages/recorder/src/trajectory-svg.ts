import type { ReplayReport } from './replay.js';

function escape(text: string): string {
  return text.replace(
    /[<>&"]/g,
    (c) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;' })[c] ?? c,
  );
}

/**
 * Both trajectories of a replay as an SVG: the recorded poses after each call (solid) and the
 * replayed ones (dashed), REP-103 (x to the right, y up), with a 1:1 scale and the largest
 * divergence in the title.
 */
export function trajectorySvg(report: ReplayReport, title = 'recorded vs replayed'): string {
  const recorded = [
    { x: 0, y: 0 },
    ...report.calls.flatMap((c) => (c.recordedPose ? [c.recordedPose.position] : [])),
  ];
  const replayed = [
    { x: 0, y: 0 },
    ...report.calls.flatMap((c) => (c.replayedPose ? [c.replayedPose.position] : [])),
  ];
  const all = [...recorded, ...replayed];
  const minX = Math.min(...all.map((p) => p.x));
  const maxX = Math.max(...all.map((p) => p.x));
  const minY = Math.min(...all.map((p) => p.y));
  const maxY = Math.max(...all.map((p) => p.y));
  const span = Math.max(maxX - minX, maxY - minY, 0.01);
  const size = 400;
  const margin = 30;
  const scale = (size - 2 * margin) / span;
  const point = (p: { x: number; y: number }) =>
    `${(margin + (p.x - minX) * scale).toFixed(2)},${(size - margin - (p.y - minY) * scale).toFixed(2)}`;
  const line = (points: { x: number; y: number }[], style: string) =>
    `<polyline fill="none" ${style} points="${points.map(point).join(' ')}"/>`;
  const heading = `${title}: max divergence ${(report.maxPositionM * 1000).toFixed(3)} mm`;
  return [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${size}" height="${size + 20}" viewBox="0 0 ${size} ${size + 20}">`,
    `<title>${escape(heading)}</title>`,
    `<rect width="100%" height="100%" fill="white"/>`,
    line(recorded, 'stroke="#1f77b4" stroke-width="3"'),
    line(replayed, 'stroke="#d62728" stroke-width="1.5" stroke-dasharray="4 3"'),
    `<text x="8" y="${size + 12}" font-family="sans-serif" font-size="11">${escape(heading)} (blue: recorded, red dashed: replayed; ${span.toFixed(3)} m across)</text>`,
    '</svg>',
    '',
  ].join('\n');
}
