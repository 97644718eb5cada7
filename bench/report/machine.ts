import { cpus, totalmem, type as osType, release } from 'node:os';

/** The machine a report was measured on, in one line. */
export function describeMachine(): string {
  const cores = cpus();
  const model = cores[0]?.model.trim() ?? 'unknown CPU';
  const memory = (totalmem() / 2 ** 30).toFixed(0);
  return `${model}, ${cores.length} cores, ${memory} GiB; ${osType()} ${release()}; Node ${process.version}`;
}
