// The e-stop on the robot's own clock: from the emergencyStop() call to the wheels stopping, and
// the steps made after the call, with a robot driving and a get_status stuck resending (its next
// replies lost) when the stop is called. Two paths in the same run, interleaved trial by trial:
// the safety lane (stop sent at once) and the old queued path (the stop sent after the pending
// request, as one request queue did). On a clean link and through a proxy losing 30 % both ways.
// The lossy link loses from the stuck request until the move has resolved, and is clean between
// trials, so setting up and resetting do not wait for resends. ESTOP_TRIALS sets the lane trials
// per link (default 200), ESTOP_QUEUED_TRIALS the queued ones (default 50, spread evenly among
// them): a queued trial waits for the stuck request by what it measures, 1-5 s, while a lane
// trial abandons it and goes on with a fresh session, so the whole run takes minutes.
import { PhysicalHAL } from '@hal/physical';
import { startEmulator } from '../tests/physical/emulator.js';
import type { Emulator } from '../tests/physical/emulator.js';
import type { Faults } from '../tests/physical/fault-proxy.js';
import { startFaultProxy } from '../tests/physical/fault-proxy.js';
import {
  estopTrial,
  percentile,
  robotClock,
  setAcceleration,
  TRIAL_ACCELERATION,
} from '../tests/physical/estop-trial.js';
import type { EstopPath, EstopTrial } from '../tests/physical/estop-trial.js';
import { reportFigure } from './report/figures.js';

const TRIALS = Number(process.env['ESTOP_TRIALS'] ?? 200);
const QUEUED_TRIALS = Math.min(TRIALS, Number(process.env['ESTOP_QUEUED_TRIALS'] ?? 50));
const LOST_REPLIES = 2;
const STEP_PERIOD_MS = 1000 / 1024;

const fmt = (ms: number) => `${ms.toFixed(2)} ms`;

function summary(trials: EstopTrial[]): {
  p50: number;
  p99: number;
  steps50: number;
  steps99: number;
  worst: number;
} {
  const latency = trials.map((t) => t.robotLatencyMs);
  const steps = trials.map((t) => t.stepsAfterCall);
  return {
    p50: percentile(latency, 50),
    p99: percentile(latency, 99),
    steps50: percentile(steps, 50),
    steps99: percentile(steps, 99),
    worst: Math.max(...latency),
  };
}

async function runLink(name: string, faults: Faults, seed: number, lossy: boolean): Promise<void> {
  // the default host timeout: the HAL resends a request every 500 ms, as on a real robot
  const emulator: Emulator = await startEmulator({ pty: false });
  await setAcceleration(emulator.udpPort, TRIAL_ACCELERATION);
  const proxy = await startFaultProxy({
    robotPort: emulator.udpPort,
    seed,
    toRobot: {},
    toHost: {},
  });
  const openHal = async (): Promise<PhysicalHAL> => {
    const fresh = new PhysicalHAL({
      mode: 'physical',
      deviceId: 'bench-estop',
      connection: { type: 'wifi', host: '127.0.0.1', udpPort: proxy.port },
    });
    await fresh.initialize();
    return fresh;
  };
  let hal = await openHal();
  const now = robotClock(emulator);
  const results: Record<EstopPath, EstopTrial[]> = { lane: [], queued: [] };
  let bad = 0;
  const failures: string[] = [];
  let rtt: ReturnType<PhysicalHAL['transportStats']>;
  // the queued trials, spread evenly among the lane trials, each side first in turn
  const queuedAt = (i: number) =>
    QUEUED_TRIALS > 0 &&
    Math.floor((i * QUEUED_TRIALS) / TRIALS) !== Math.floor(((i + 1) * QUEUED_TRIALS) / TRIALS);
  try {
    for (let i = 0; i < TRIALS; i++) {
      const paths: EstopPath[] = !queuedAt(i)
        ? ['lane']
        : i % 2 === 0
          ? ['lane', 'queued']
          : ['queued', 'lane'];
      for (const path of paths) {
        try {
          const trial = await estopTrial({
            hal,
            emulator,
            proxy,
            now,
            path,
            runMs: 20 + ((i * 7) % 40),
            lostReplies: LOST_REPLIES,
            reopen: openHal,
            faults,
          });
          hal = trial.hal;
          if (!trial.estop.success || trial.move.code !== 'EMERGENCY_STOPPED') {
            bad += 1;
            failures.push(
              `${path}: estop ${trial.estop.code ?? 'ok'}, move ${trial.move.code ?? 'ok'}`,
            );
          }
          results[path].push(trial);
        } catch (error) {
          // a lossy link can lose every resend of one request: count it, and go on
          failures.push(`${path}: ${String(error)}`);
          if (!hal.isReady()) {
            await hal.cleanup();
            hal = await openHal();
          }
          await hal.safety.resetEmergencyStop();
        }
      }
    }
    rtt = hal.transportStats();
  } finally {
    await hal.cleanup();
    await proxy.close();
    await emulator.stop();
  }
  const lane = summary(results.lane);
  const queued = summary(results.queued);
  console.log(
    `\n${name}: ${TRIALS} lane and ${QUEUED_TRIALS} queued trials, ${LOST_REPLIES} get_status replies lost at the call`,
  );
  console.log(
    `  round trip through the link: p50 ${fmt(rtt?.rttP50Ms ?? 0)}, p99 ${fmt(rtt?.rttP99Ms ?? 0)}; one step ${fmt(STEP_PERIOD_MS)}`,
  );
  for (const [label, s] of [
    ['safety lane', lane],
    ['queued (old)', queued],
  ] as const) {
    console.log(
      `  ${label.padEnd(13)} call -> wheels stopped (robot clock): p50 ${fmt(s.p50)}, p99 ${fmt(s.p99)}, max ${fmt(s.worst)}; steps after the call: p50 ${s.steps50}, p99 ${s.steps99}`,
    );
  }
  console.log(
    `  ratio queued / lane: p50 ${(queued.p50 / lane.p50).toFixed(1)}x, p99 ${(queued.p99 / lane.p99).toFixed(1)}x; trials that did not stop and latch: ${bad}`,
  );
  if (failures.length > 0) {
    console.log(
      `  trials that failed or could not run (${failures.length}): ${failures.join('; ')}`,
    );
  }
  const roundTrip =
    rtt === undefined
      ? 'the round trip was not measured'
      : `round trip through the link measured in this run, on the last trial's session: p50 ${fmt(rtt.rttP50Ms)}, p99 ${fmt(rtt.rttP99Ms)}`;
  const trialsNote =
    `${results.lane.length} lane and ${results.queued.length} queued trials on the robot's clock, ` +
    `interleaved, ${LOST_REPLIES} get_status replies lost at the call; ${bad} did not stop and latch, ` +
    `${failures.length} failed or could not run`;
  const alternative = (stat: string, value: number) => ({
    name: `queued path (old: the stop waits for the pending request), ${stat}`,
    value,
  });
  for (const [stat, lanePercentile, queuedPercentile] of [
    ['p50', lane.p50, queued.p50],
    ['p99', lane.p99, queued.p99],
  ] as const) {
    const p99 = stat === 'p99';
    reportFigure({
      bench: 'estop',
      name: `${name}: emergencyStop() call to motors stopped, safety lane, ${stat}`,
      value: lanePercentile,
      unit: 'ms',
      better: 'lower',
      alternative: alternative(stat, queuedPercentile),
      goal: !p99 ? undefined : lossy ? '< 100 ms' : 'within one round trip plus one step period',
      ...(p99 && lossy ? { met: lanePercentile < 100 } : {}),
      note: p99
        ? `${trialsNote}; ${roundTrip}; one step period ${fmt(STEP_PERIOD_MS)}`
        : trialsNote,
    });
  }
  for (const [stat, lanePercentile, queuedPercentile] of [
    ['p50', lane.steps50, queued.steps50],
    ['p99', lane.steps99, queued.steps99],
  ] as const) {
    reportFigure({
      bench: 'estop',
      name: `${name}: steps after the emergencyStop() call, safety lane, ${stat}`,
      value: lanePercentile,
      unit: 'steps',
      better: 'lower',
      alternative: alternative(stat, queuedPercentile),
      note: trialsNote,
    });
  }
}

// ESTOP_LINKS=clean or =lossy runs one link only
const links = process.env['ESTOP_LINKS'] ?? 'clean,lossy';
if (links.includes('clean')) await runLink('clean link', {}, 1, false);
if (links.includes('lossy')) await runLink('30 % loss both ways', { drop: 0.3 }, 2, true);
