// Runs the compliance runner for `hal test hal`: progress on stderr as checks finish, the report
// as a table (or JSON with --json) on stdout, exit code 0 only when no check failed.
import {
  DEFAULT_SEEN_WINDOW_MS,
  devicesSeenOnNats,
  formatReport,
  runCompliance,
} from '@hal/compliance';
import type { CheckGroup, ComplianceReport, ProgressEvent, SpecCapability } from '@hal/compliance';
import { openConnection } from '@hal/nats';
import { HalError } from '@hal/types';
import { CliError } from '../cli-error.js';
import type { CommandContext } from '../commands/context.js';
import { emit, progress } from '../io.js';
import { natsConnectOptions } from '../nats-options.js';
import type { NatsCliOptions } from '../nats-options.js';

export interface TestHalOptions extends NatsCliOptions {
  device?: string;
  /** Every device seen announcing itself on NATS, one after the other. */
  all?: boolean;
  /** Also check the device's mDNS announcement. */
  mdns?: boolean;
  capability?: SpecCapability[];
  group?: CheckGroup[];
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

function failedText(report: ComplianceReport): string {
  const failed = report.checks.filter((c) => c.status === 'fail');
  return `${failed.length} of ${report.checks.length} checks failed: ${failed.map((c) => c.id).join(', ')}`;
}

async function checkOne(
  { io, global }: CommandContext,
  nc: Awaited<ReturnType<typeof openConnection>>,
  device: string | undefined,
  options: TestHalOptions,
): Promise<ComplianceReport> {
  const output = global();
  return runCompliance({
    connection: nc,
    device,
    capabilities: options.capability,
    groups: options.group,
    ...(options.samples === undefined ? {} : { samples: options.samples }),
    ...(options.judge === undefined ? {} : { judge: options.judge }),
    ...(options.mdns === true ? { mdns: true } : {}),
    signal: io.signal,
    onProgress: (event) => {
      const line = progressLine(event);
      if (line !== undefined) progress(io, output, line);
    },
  });
}

export async function runTestHal(
  ctx: CommandContext,
  suite: string,
  options: TestHalOptions,
): Promise<void> {
  const { io, global } = ctx;
  if (options.all === true && options.device !== undefined) {
    throw new CliError('USAGE', '--all tests every device seen on NATS: leave out --device');
  }
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
    if (options.all !== true) {
      const report = await checkOne(ctx, nc, options.device, options);
      emit(io, output, report, () => formatReport(report));
      if (report.aborted) throw new CliError('FAILED', 'interrupted before every check ran');
      if (!report.ok) throw new CliError('CHECK_FAILED', failedText(report));
      return;
    }
    progress(io, output, `listening ${DEFAULT_SEEN_WINDOW_MS} ms for devices announcing on NATS`);
    const seen = await devicesSeenOnNats({ connection: nc });
    if (seen.length === 0) {
      throw new HalError(
        'NOT_CONNECTED',
        `no device announced its capabilities on NATS within ${DEFAULT_SEEN_WINDOW_MS} ms`,
      );
    }
    progress(io, output, `seen: ${seen.map((d) => d.deviceId).join(', ')}`);
    const reports: ComplianceReport[] = [];
    for (const device of seen) {
      if (io.signal?.aborted === true) break;
      reports.push(await checkOne(ctx, nc, device.address, options));
    }
    emit(io, output, reports, () => reports.map((r) => formatReport(r)).join('\n'));
    if (reports.length < seen.length || reports.some((r) => r.aborted)) {
      throw new CliError('FAILED', 'interrupted before every device was checked');
    }
    const failing = reports.filter((r) => !r.ok);
    if (failing.length > 0) {
      throw new CliError(
        'CHECK_FAILED',
        `${failing.length} of ${reports.length} devices failed: ${failing
          .map((r) => `${r.deviceId} (${failedText(r)})`)
          .join('; ')}`,
      );
    }
  } finally {
    await nc.close();
  }
}
