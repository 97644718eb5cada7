// The Tafy HAL spec's performance guidelines, quoted: "start-up under 1 s from power to capability
// announcement, command processing under 10 ms, memory under 10 MB for simple drivers". Measured
// here for the NATS gateway as users start it (`hal serve --sim --nats`, a process run from
// source as `pnpm hal` runs it, and the built CLI when `pnpm build` has written it) and for the
// emulated cube (the firmware core on the host), each
// beside an alternative in the same run, interleaved: for the gateway, the least a Node program
// on NATS does (bench/alternatives/nats-echo.ts: connect, announce, answer requests), so the
// ratio shows what our gateway adds to Node and nats.js. Starts its own nats-server on 127.0.0.1.
import { spawn } from 'node:child_process';
import type { ChildProcessByStdio } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import type { Readable, Writable } from 'node:stream';
import { fileURLToPath } from 'node:url';
import { connect } from '@nats-io/transport-node';
import type { NatsConnection } from '@nats-io/transport-node';
import { delay } from '@hal/types';
import { startEmulator } from '../tests/physical/emulator.js';
import type { Emulator } from '../tests/physical/emulator.js';
import { startNatsServer } from '../tests/nats/nats-server.js';
import { openRawUdpClient, setLedJson } from './raw-udp-client.js';
import { percentile, reportFigure } from './report/figures.js';

const MAIN = fileURLToPath(new URL('../packages/cli/src/main.ts', import.meta.url));
const ECHO = fileURLToPath(new URL('./alternatives/nats-echo.ts', import.meta.url));
// the CLI as installed from the packages (`pnpm build` writes it; `pnpm test` builds first)
const BUILT_MAIN = fileURLToPath(new URL('../packages/cli/dist/main.js', import.meta.url));
const STARTS = 5;
const ROUNDS = 500;
const WARMUP = 50;
const DEVICE = 'bench-gw';
// the spec's figures, quoted
const SPEC = { startupMs: 1000, commandMs: 10, memoryBytes: 10 * 1024 * 1024 };

type Child = ChildProcessByStdio<Writable, Readable, Readable>;
const children = new Set<Child>();
process.on('exit', () => {
  for (const child of children) child.kill('SIGKILL');
});

/** Runs a script from source (tsx, as `pnpm hal` does), or a built one as it is (`built`). */
function spawnNode(script: string, args: readonly string[], built = false): Child {
  const loader = built ? [] : ['--conditions=@hal/source', '--import', 'tsx'];
  const child = spawn(process.execPath, [...loader, script, ...args], {
    stdio: ['pipe', 'pipe', 'pipe'],
  });
  children.add(child);
  child.once('exit', () => children.delete(child));
  child.stdout.resume();
  child.stderr.resume();
  return child;
}

async function stop(child: Child): Promise<void> {
  if (child.exitCode !== null || child.signalCode !== null) return;
  const exited = new Promise((resolve) => child.once('exit', resolve));
  child.stdin.end();
  child.kill('SIGINT');
  const timer = setTimeout(() => child.kill('SIGKILL'), 10_000);
  await exited;
  clearTimeout(timer);
}

/** A process's resident memory, bytes (VmRSS of /proc/PID/status). */
function rssBytes(pid: number): number {
  const line = /VmRSS:\s+(\d+) kB/.exec(readFileSync(`/proc/${pid}/status`, 'utf8'));
  if (line === null) throw new Error(`no VmRSS for process ${pid}`);
  return Number(line[1]) * 1024;
}

function within<T>(promise: Promise<T>, ms: number, what: string): Promise<T> {
  let timer: NodeJS.Timeout | undefined;
  return Promise.race([
    promise,
    new Promise<never>((_, reject) => {
      timer = setTimeout(() => reject(new Error(`${what}: nothing in ${ms} ms`)), ms);
    }),
  ]).finally(() => clearTimeout(timer));
}

/** Spawns a program and measures the time from spawn to its first message on `subject`. */
async function startup(
  nc: NatsConnection,
  subject: string,
  start: () => Child,
): Promise<{ ms: number; child: Child }> {
  const sub = nc.subscribe(subject, { max: 1 });
  const first = (async () => {
    for await (const _msg of sub) return performance.now();
    throw new Error(`${subject}: subscription ended`);
  })();
  await nc.flush();
  const t0 = performance.now();
  const child = start();
  const t1 = await within(first, 60_000, subject);
  return { ms: t1 - t0, child };
}

const startGateway = (url: string) => () =>
  spawnNode(MAIN, ['serve', '--sim', '--nats', url, '--device', DEVICE, '--no-mdns']);
const startEcho = (url: string) => () => spawnNode(ECHO, [url]);
const startBuiltGateway = (url: string) => () =>
  spawnNode(BUILT_MAIN, ['serve', '--sim', '--nats', url, '--device', DEVICE, '--no-mdns'], true);
const announceSubject = `hal.v1.dev.${DEVICE}.system.capability.announce`;

const ms = (v: number) => `${v.toFixed(v < 10 ? 2 : 0)} ms`;
const mb = (v: number) => `${(v / 1024 / 1024).toFixed(1)} MB`;

function figure(
  name: string,
  value: number,
  unit: string,
  limit: number,
  alternative?: { name: string; value: number },
  note?: string,
) {
  reportFigure({
    bench: 'nats-spec',
    name,
    value,
    unit,
    better: 'lower',
    ...(alternative === undefined ? {} : { alternative }),
    goal: `< ${limit} ${unit} (the spec's guideline, quoted)`,
    met: value < limit,
    ...(note === undefined ? {} : { note }),
  });
}

async function gateway(url: string): Promise<void> {
  const nc = await connect({ servers: url });
  const built = existsSync(BUILT_MAIN);
  const starts = { gateway: [] as number[], echo: [] as number[], built: [] as number[] };
  let builtRss = 0;
  let gw: Child | undefined;
  let echo: Child | undefined;
  for (let i = 0; i < STARTS; i++) {
    const g = await startup(nc, announceSubject, startGateway(url));
    const e = await startup(nc, 'bench.echo.up', startEcho(url));
    starts.gateway.push(g.ms);
    starts.echo.push(e.ms);
    if (built) {
      const b = await startup(nc, announceSubject, startBuiltGateway(url));
      starts.built.push(b.ms);
      await delay(1000); // serving, streaming at 20 Hz
      builtRss = Math.max(builtRss, rssBytes(b.child.pid ?? 0));
      await stop(b.child);
    }
    if (i < STARTS - 1) await Promise.all([stop(g.child), stop(e.child)]);
    else [gw, echo] = [g.child, e.child];
  }
  if (built) {
    const bP50 = percentile(starts.built, 50);
    console.log(
      `gateway start-up, built CLI (packages/cli/dist): p50 ${ms(bP50)} (max ${ms(Math.max(...starts.built))}); spec < ${SPEC.startupMs} ms`,
    );
    figure(
      'gateway start-up to capability announcement, built CLI (p50 of 5)',
      bP50,
      'ms',
      SPEC.startupMs,
      undefined,
      'node packages/cli/dist/main.js serve --sim --nats: the CLI as installed from its packages',
    );
    console.log(`gateway memory (RSS), built CLI, 1 s after start: ${mb(builtRss)}; spec < 10 MB`);
    figure(
      'gateway memory (RSS), built CLI, 1 s after start',
      builtRss / 1024 / 1024,
      'MB',
      10,
      undefined,
      'the largest of 5 starts, each read while serving the simulator for 1 s',
    );
  } else {
    console.log('gateway start-up, built CLI: not measured (no packages/cli/dist: run pnpm build)');
  }
  const gP50 = percentile(starts.gateway, 50);
  const eP50 = percentile(starts.echo, 50);
  console.log(
    `gateway start-up to capability announcement: p50 ${ms(gP50)} (max ${ms(Math.max(...starts.gateway))}) vs a bare nats.js program ${ms(eP50)}; spec < ${SPEC.startupMs} ms`,
  );
  figure(
    'gateway start-up to capability announcement (p50 of 5)',
    gP50,
    'ms',
    SPEC.startupMs,
    {
      name: 'bare nats.js program to its first publish',
      value: eP50,
    },
    'from spawn of `hal serve --sim --nats` run from source (node --import tsx), as `pnpm hal` runs it',
  );

  // a stop command, as a spec client sends it, beside an echo of the same bytes
  const stopCmd = new TextEncoder().encode(
    JSON.stringify({
      hal_major: 1,
      hal_minor: 0,
      schema: 'bench',
      device_id: 'bench-client',
      caps: [],
      ts: new Date().toISOString(),
      payload: { linear_vel_m_per_s: 0, angular_vel_rad_per_s: 0 },
    }),
  );
  const rtt = { gateway: [] as number[], echo: [] as number[] };
  for (let i = 0; i < WARMUP + ROUNDS; i++) {
    for (const [path, subject] of [
      ['gateway', `hal.v1.dev.${DEVICE}.motor.differential.cmd`],
      ['echo', 'bench.echo'],
    ] as const) {
      const t0 = performance.now();
      await nc.request(subject, stopCmd, { timeout: 5000 });
      if (i >= WARMUP) rtt[path].push(performance.now() - t0);
    }
  }
  for (const p of [50, 99]) {
    const g = percentile(rtt.gateway, p);
    const e = percentile(rtt.echo, p);
    console.log(
      `gateway stop command round trip p${p}: ${ms(g)} vs raw request-reply ${ms(e)} (${(g / e).toFixed(1)}x); spec < ${SPEC.commandMs} ms`,
    );
    figure(
      `gateway command round trip p${p}`,
      g,
      'ms',
      SPEC.commandMs,
      {
        name: 'raw nats request-reply (echo)',
        value: e,
      },
      'measured around the NATS request: client, nats-server and gateway, all on this machine',
    );
  }
  const gRss = rssBytes(gw?.pid ?? 0);
  const eRss = rssBytes(echo?.pid ?? 0);
  console.log(
    `gateway memory (RSS): ${mb(gRss)} vs a bare nats.js program ${mb(eRss)}; spec < 10 MB`,
  );
  figure(
    'gateway memory (RSS)',
    gRss / 1024 / 1024,
    'MB',
    10,
    {
      name: 'bare nats.js program',
      value: eRss / 1024 / 1024,
    },
    'a Node process: V8 and the runtime alone are far above 10 MB, whatever the program',
  );
  await Promise.all([gw, echo].map((child) => (child === undefined ? undefined : stop(child))));
  await nc.close();
}

async function cube(): Promise<void> {
  const starts: number[] = [];
  let last: Emulator | undefined;
  for (let i = 0; i < STARTS; i++) {
    const t0 = performance.now();
    const emulator = await startEmulator({ pty: false, hostTimeoutMs: 10_000 });
    const client = await within(openRawUdpClient(emulator.udpPort), 5000, 'hello');
    starts.push(performance.now() - t0);
    client.close();
    if (i < STARTS - 1) await emulator.stop();
    else last = emulator;
  }
  const p50 = percentile(starts, 50);
  console.log(
    `emulated cube start-up to hello reply (device info, capabilities): p50 ${ms(p50)}; spec < ${SPEC.startupMs} ms`,
  );
  figure(
    'emulated cube start-up to its capabilities (p50 of 5)',
    p50,
    'ms',
    SPEC.startupMs,
    undefined,
    'spawn of cube-emulator to the hello reply over UDP, which carries the capabilities; on a board, boot and WiFi come first',
  );
  if (last === undefined) return;
  const client = await within(openRawUdpClient(last.udpPort), 5000, 'hello');
  const times: number[] = [];
  for (let i = 0; i < WARMUP + ROUNDS; i++) {
    const t0 = performance.now();
    await within(client.ask(setLedJson(i + 2, client.sid, i)), 5000, 'set_led');
    if (i >= WARMUP) times.push(performance.now() - t0);
  }
  for (const p of [50, 99]) {
    const v = percentile(times, p);
    console.log(
      `emulated cube command (set_led) UDP round trip p${p}: ${ms(v)}; spec < ${SPEC.commandMs} ms`,
    );
    figure(
      `emulated cube command round trip p${p}`,
      v,
      'ms',
      SPEC.commandMs,
      undefined,
      'raw UDP on 127.0.0.1; PhysicalHAL against the same raw client: physical.bench.ts',
    );
  }
  const rss = rssBytes(last.pid);
  console.log(`emulated cube memory (RSS): ${mb(rss)}; spec < 10 MB`);
  figure(
    'emulated cube memory (RSS)',
    rss / 1024 / 1024,
    'MB',
    10,
    undefined,
    'the host build of the firmware core with its emulator shell, not the board',
  );
  client.close();
  await last.stop();
}

const server = await startNatsServer();
try {
  await gateway(server.url);
  await cube();
} finally {
  await server.stop();
}
process.exit(0);
