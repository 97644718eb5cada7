// Runs the compliance runner for `hal test hal`: progress on stderr as checks finish, the report
// as a table (or JSON with --json) on stdout, exit code 0 only when no check failed.
import { formatReport, runCompliance } from '@hal/compliance';
import type { ProgressEvent, SpecCapability } from '@hal/compliance';
import { openConnection } from '@hal/nats';
import { CliError } from '../cli-error.js';
import type { CommandContext } from '../commands/index.js';
import { emit, progress } from '../io.js';
import { natsConnectOptions } from '../nats-options.js';
import type { NatsCliOptions } from '../nats-options.js';

export interface TestHalOptions extends NatsCliOptions {
  device?: string;
  capability?: SpecCapability[];
  samples?: number;
  judge?: 'p50' | 'p99';
}

function progressLine(event: ProgressEvent): string | undefined {
  if (event.type === 'device')
    return `checking ${event.deviceId} (${event.caps.length} capabilities announced)`;
  if (event.type === 'result') {
    const r = event.result;
    return `  ${r.status.toUpperCase().padEnd(4)}  ${r.id}${r.status === 'fail' ? `: ${r.reason}` : ''}`;
  }
  return undefined;
}

export async function runTestHal(
  { io, global }: CommandContext,
  suite: string,
  options: TestHalOptions,
): Promise<void> {
  if (suite !== 'hal') {
    throw new CliError(
      'USAGE',
      `hal test knows one suite, "hal" (hal test hal --device X), got "${suite}"`,
    );
  }
  const output = global();
  const connect = natsConnectOptions(options, io.env, 'hal-test');
  const nc = await openConnection(connect);
  try {
    const report = await runCompliance({
      connection: nc,
      device: options.device,
      capabilities: options.capability,
      ...(options.samples === undefined ? {} : { samples: options.samples }),
      ...(options.judge === undefined ? {} : { judge: options.judge }),
      signal: io.signal,
      onProgress: (event) => {
        const line = progressLine(event);
        if (line !== undefined) progress(io, output, line);
      },
    });
    emit(io, output, report, () => formatReport(report));
    if (report.aborted) throw new CliError('FAILED', 'interrupted before every check ran');
    if (!report.ok) {
      throw new CliError(
        'CHECK_FAILED',
        `${report.summary.failed} of ${report.checks.length} checks failed: ${report.checks
          .filter((c) => c.status === 'fail')
          .map((c) => c.id)
          .join(', ')}`,
      );
    }
  } finally {
    await nc.close();
  }
}
