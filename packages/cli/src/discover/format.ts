// `hal discover`'s human output: one robot per line, aligned.
import type { DiscoveredRobot } from '@hal/discovery';

/** A table of the robots found, or a sentence when there are none. */
export function formatRobots(robots: readonly DiscoveredRobot[], timeoutMs: number): string {
  if (robots.length === 0) return `no robots answered within ${timeoutMs} ms`;
  const rows = robots.map((r) => [
    r.deviceId,
    `${r.onThisMachine ? '127.0.0.1' : (r.addresses.find((a) => !a.includes(':')) ?? r.addresses[0] ?? '?')}:${r.port}`,
    r.host,
    r.protocolVersion,
    r.requiresKey ? `key (${r.auth})` : 'none',
    r.capabilities.join(' '),
  ]);
  const header = ['DEVICE', 'ADDRESS', 'HOST', 'PROTOCOL', 'AUTH', 'CAPABILITIES'];
  const table = [header, ...rows];
  const widths = header.map((_, i) => Math.max(...table.map((row) => row[i]?.length ?? 0)));
  return table
    .map((row) =>
      row.map((cell, i) => (i === row.length - 1 ? cell : cell.padEnd(widths[i] ?? 0))).join('  '),
    )
    .join('\n');
}
