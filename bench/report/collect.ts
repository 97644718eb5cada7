import { BENCH_JSON_PREFIX, RecordSchema } from './figures.js';
import type { BenchRecord } from './figures.js';

/** What one benchmark's output held: its records, and the lines that claimed to be one but were not. */
export interface Collected {
  records: BenchRecord[];
  malformed: string[];
}

/** Picks the `BENCH_JSON` records out of a benchmark's output, checking each against the schema. */
export function collectRecords(output: string): Collected {
  const records: BenchRecord[] = [];
  const malformed: string[] = [];
  for (const line of output.split('\n')) {
    if (!line.startsWith(BENCH_JSON_PREFIX)) continue;
    const text = line.slice(BENCH_JSON_PREFIX.length);
    let json: unknown;
    try {
      json = JSON.parse(text);
    } catch {
      malformed.push(text);
      continue;
    }
    const parsed = RecordSchema.safeParse(json);
    if (parsed.success) records.push(parsed.data);
    else malformed.push(text);
  }
  return { records, malformed };
}
