import type { EvalReport } from '../run-eval.js';
import { reportGroups } from './table.js';

const PALETTE = ['#1d4ed8', '#d62828', '#2a9d3f', '#f77f00', '#7b2cbf', '#00a6a6', '#6b7280'];
const escape = (text: string) =>
  text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

/**
 * A bar chart of the success rate by group, one bar per agent side by side in each group, with
 * the 95 % interval over tasks (a bootstrap over tasks) as a whisker. Plain SVG, no script; the
 * same report gives the same bytes.
 */
export function successSvg(report: EvalReport): string {
  const groups = [...reportGroups(report), 'overall'];
  const agents = report.scores.agents;
  const bar = 18;
  const gap = 26;
  const groupWidth = agents.length * bar + gap;
  const left = 44;
  const top = 20;
  const height = 200;
  const width = left + groups.length * groupWidth + 20;
  const legendY = top + height + 40;
  const svgHeight = legendY + agents.length * 16 + 10;
  const y = (rate: number) => top + height - rate * height;
  const parts: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${svgHeight}" viewBox="0 0 ${width} ${svgHeight}" font-family="sans-serif" font-size="11">`,
    `<title>Success rate by group (seed ${report.scores.seed}, ${report.scores.trialsPerTask} trials per task)</title>`,
  ];
  for (const tick of [0, 0.25, 0.5, 0.75, 1]) {
    parts.push(
      `<line x1="${left}" x2="${width - 10}" y1="${y(tick)}" y2="${y(tick)}" stroke="#ddd"/>`,
      `<text x="${left - 6}" y="${y(tick) + 4}" text-anchor="end">${tick * 100}%</text>`,
    );
  }
  groups.forEach((group, g) => {
    const x0 = left + g * groupWidth + gap / 2;
    agents.forEach((agent, a) => {
      const rate =
        group === 'overall' ? agent.overall : agent.groups.find((s) => s.group === group)?.success;
      // no bar for an agent with no scored trial (its model failed): it is no 0 %
      if (rate === undefined || rate.trials === 0) return;
      const x = x0 + a * bar;
      const colour = PALETTE[a % PALETTE.length] ?? '#000';
      const h = Math.max(rate.rate * height, 0.5);
      parts.push(
        `<rect x="${x}" y="${y(rate.rate)}" width="${bar - 2}" height="${h}" fill="${colour}"><title>${escape(agent.agent)} ${escape(group)}: ${rate.successes}/${rate.trials}</title></rect>`,
        `<line x1="${x + bar / 2 - 1}" x2="${x + bar / 2 - 1}" y1="${y(rate.low)}" y2="${y(rate.high)}" stroke="#111"/>`,
      );
    });
    parts.push(
      `<text x="${x0 + (agents.length * bar) / 2}" y="${top + height + 16}" text-anchor="middle">${escape(group)}</text>`,
    );
  });
  agents.forEach((agent, a) => {
    const colour = PALETTE[a % PALETTE.length] ?? '#000';
    const ly = legendY + a * 16;
    parts.push(
      `<rect x="${left}" y="${ly - 9}" width="10" height="10" fill="${colour}"/>`,
      `<text x="${left + 16}" y="${ly}">${escape(agent.agent)}${agent.usesGroundTruth ? ' (oracle: reads the ground truth)' : ''}${agent.modelFailure === null ? '' : ' (model failed, see eval.md)'}</text>`,
    );
  });
  parts.push('</svg>');
  return `${parts.join('\n')}\n`;
}
