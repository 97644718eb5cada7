// CPU time the hypervisor gave to other guests while this machine's CPUs wanted to run: the
// `steal` column of /proc/stat (Linux only). On a shared virtual machine it is where a
// round trip's rare millisecond stalls come from, so a benchmark of tail latency reports it
// beside its percentiles.
import { readFileSync } from 'node:fs';

/** Clock ticks per second of /proc/stat (USER_HZ, 100 on every mainstream Linux build). */
const USER_HZ = 100;

/** The stolen time, all CPUs together, in ms, from the text of /proc/stat; undefined if absent. */
export function stolenMsFromProcStat(text: string): number | undefined {
  const line = text.split('\n').find((l) => l.startsWith('cpu '));
  // cpu user nice system idle iowait irq softirq steal ...
  const steal = line?.trim().split(/\s+/)[8];
  if (steal === undefined || !/^\d+$/.test(steal)) return undefined;
  return (Number(steal) * 1000) / USER_HZ;
}

/** The stolen time so far on this machine (ms), or undefined where it cannot be read. */
export function stolenMs(): number | undefined {
  try {
    return stolenMsFromProcStat(readFileSync('/proc/stat', 'utf8'));
  } catch {
    return undefined;
  }
}
