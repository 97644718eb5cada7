// Writes `hal eval`'s reports into a folder: eval.json (the whole report), eval.md and eval.svg.
import { mkdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { markdownReport, successSvg } from '@hal/eval';
import type { EvalReport } from '@hal/eval';

/** The files written, by kind. */
export interface WrittenReports {
  json: string;
  markdown: string;
  svg: string;
}

export async function writeReports(dir: string, report: EvalReport): Promise<WrittenReports> {
  await mkdir(dir, { recursive: true });
  const files = {
    json: join(dir, 'eval.json'),
    markdown: join(dir, 'eval.md'),
    svg: join(dir, 'eval.svg'),
  };
  await writeFile(files.json, `${JSON.stringify(report, null, 2)}\n`);
  await writeFile(files.markdown, markdownReport(report, { plotFile: 'eval.svg' }));
  await writeFile(files.svg, successSvg(report));
  return files;
}
