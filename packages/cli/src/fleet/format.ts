// Human-readable output of `hal fleet` (with --json the documents are written as they are).
import type { FleetReport, FormationReport } from '@hal/fleet';
import type { DeviceHealth } from '@hal/fleet/node';

const pad = (text: string, width: number): string => text.padEnd(width);

/** The library's reset hints (`resetEmergencyStop()`), as the command to type. */
const LIBRARY_RESET_HINT =
  /;? *(?:call safety\.resetEmergencyStop\(\) first|reset it with resetEmergencyStop\(\))/;

/** A member's error message, its reset hint naming `hal fleet reset`. */
export function fleetErrorText(message: string | undefined): string {
  if (message === undefined) return '';
  return LIBRARY_RESET_HINT.test(message)
    ? message.replace(LIBRARY_RESET_HINT, '; reset it with: hal fleet reset (and the same devices)')
    : message;
}

/** One line per device: its own result, or its code and message. */
export function formatReport(title: string, report: FleetReport): string {
  const width = Math.max(6, ...report.results.map((r) => r.device.length)) + 2;
  const lines = report.results.map((r) =>
    r.result.success
      ? `${pad(r.device, width)}ok    ${r.result.executionTime ?? 0} ms`
      : `${pad(r.device, width)}FAIL  ${r.result.code}: ${fleetErrorText(r.result.error)}`,
  );
  const summary = `${title}: ${report.succeeded.length} ok, ${report.failed.length} failed, ${report.executionTime} ms`;
  return [...lines, summary].join('\n');
}

/** One line per device: online, e-stop, pose. */
export function formatHealth(health: DeviceHealth[]): string {
  const width = Math.max(6, ...health.map((h) => h.device.length)) + 2;
  return health
    .map((h) => {
      const state = h.online ? 'online ' : 'OFFLINE';
      const estop = h.emergencyStopped ? '  E-STOP' : '';
      const pose = h.telemetry?.pose;
      const where =
        pose === undefined
          ? ''
          : `  x=${pose.x.toFixed(3)} y=${pose.y.toFixed(3)} yaw=${((pose.yaw * 180) / Math.PI).toFixed(1)}deg`;
      const error = h.online || h.lastError === undefined ? '' : `  (${h.lastError})`;
      return `${pad(h.device, width)}${state}${estop}${where}${error}`;
    })
    .join('\n');
}

/** The formation's end: why, and each follower's distance from its slot. */
export function formatFormation(report: FormationReport): string {
  const lines = report.followers.map(
    (f) =>
      `  ${f.device}: ${f.errorM === undefined ? 'pose unknown' : `${(f.errorM * 100).toFixed(1)} cm from its slot`}`,
  );
  return [
    `formation ended (${report.reason}) after ${report.ticks} ticks, leader ${report.leader}`,
    ...lines,
  ].join('\n');
}
