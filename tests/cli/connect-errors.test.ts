// What `hal` says when it cannot reach a robot, run against the real things: the emulated robot
// with and without a key, a UDP port where nothing answers, a WebSocket server that refuses the
// token, and a NATS address with no server. Each error names what failed and why, once.
import { createSocket } from 'node:dgram';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Socket } from 'node:dgram';
import { runHal } from '@hal/cli';
import { serveHal } from '@hal/remote/server';
import type { HalServer } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { freePort, startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';

const KEY = '00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff';
const OTHER_KEY = 'ffeeddccbbaa99887766554433221100ffeeddccbbaa99887766554433221100';

interface ErrorDoc {
  error: { code: string; message: string };
}

/** Runs `hal --json argv`; its exit code and the JSON documents it wrote on stderr. */
async function halJson(argv: string[]): Promise<{ code: number; errors: ErrorDoc[] }> {
  const io = captureIO();
  const code = await runHal(['--json', ...argv], io);
  const lines = io
    .stderr()
    .split('\n')
    .filter((line) => line !== '');
  // every line on stderr is JSON with --json: nothing in another style
  const docs = lines.map((line) => JSON.parse(line) as Record<string, unknown>);
  return {
    code,
    errors: docs.filter((d): d is ErrorDoc & Record<string, unknown> => 'error' in d),
  };
}

let keyed: Emulator;
let open: Emulator;
let silent: Socket;
let silentPort: number;

beforeAll(async () => {
  keyed = await startEmulator({ key: KEY, pty: false, timeScale: 4 });
  open = await startEmulator({ pty: false, timeScale: 4 });
  // a UDP port with a socket on it that never answers: a robot that is off, or elsewhere
  silent = createSocket('udp4');
  await new Promise<void>((resolve) => silent.bind(0, '127.0.0.1', resolve));
  silentPort = silent.address().port;
});
afterAll(async () => {
  silent.close();
  await stopAllEmulators();
});

describe('hal on a robot over UDP', () => {
  it('keeps saying hello for the whole --connect-timeout, beyond the 6 s of one request', async () => {
    const started = Date.now();
    const { code, errors } = await halJson([
      'status',
      '--udp',
      `127.0.0.1:${silentPort}`,
      '--connect-timeout',
      '7500',
    ]);
    const waited = Date.now() - started;
    expect(code).toBe(1);
    expect(errors).toHaveLength(1);
    expect(errors[0]!.error.code).toBe('NOT_CONNECTED');
    expect(errors[0]!.error.message).toMatch(
      new RegExp(
        `^no answer from the robot at udp 127\\.0\\.0\\.1:${silentPort} within 7500 ms: nothing came back\\. Is it powered, on this network, at this address and port\\?`,
      ),
    );
    // it did not give up early (at the 6 s of one request's retries)
    expect(waited).toBeGreaterThanOrEqual(7400);
  }, 20_000);

  it('says the key is wrong when the robot answers with its own key', async () => {
    const before = keyed.events.length;
    const { code, errors } = await halJson([
      'drive',
      'forward',
      '0.05',
      '--udp',
      `127.0.0.1:${keyed.udpPort}`,
      '--key',
      OTHER_KEY,
      '--time-scale',
      '4',
    ]);
    expect(code).toBe(1);
    expect(errors).toEqual([
      {
        error: expect.objectContaining({
          code: 'AUTH_FAILED',
          message: `the robot at udp 127.0.0.1:${keyed.udpPort} answered "hello" but its replies do not carry our MAC: the key is wrong (the robot has another one)`,
        }),
      },
    ]);
    // nothing was executed
    expect(keyed.events.slice(before).some((e) => e.event === 'move_started')).toBe(false);
  });

  it('says the robot has no key when a key is given to a robot without one', async () => {
    const { code, errors } = await halJson([
      'status',
      '--udp',
      `127.0.0.1:${open.udpPort}`,
      '--key',
      KEY,
      '--time-scale',
      '4',
    ]);
    expect(code).toBe(1);
    expect(errors[0]!.error).toMatchObject({
      code: 'AUTH_FAILED',
      message: expect.stringMatching(/answered "hello" without a MAC: it has no key/),
    });
  });

  it('connects with the right key', async () => {
    const io = captureIO();
    const argv = ['--json', 'status', '--udp', `127.0.0.1:${keyed.udpPort}`, '--key', KEY];
    expect(await runHal([...argv, '--time-scale', '4'], io), io.stderr()).toBe(0);
  });
});

describe('hal on a link that cannot be opened', () => {
  it("names a serial port that does not exist with the system's reason, at once", async () => {
    const path = join(tmpdir(), `hal-no-such-port-${process.pid}`);
    const { code, errors } = await halJson(['status', '--serial', path]);
    expect(code).toBe(1);
    expect(errors).toHaveLength(1);
    expect(errors[0]!.error.code).toBe('NOT_CONNECTED');
    expect(errors[0]!.error.message).toMatch(
      new RegExp(`^cannot open serial port ${path}: .*No such file or directory`),
    );
    // no timeout was waited for, so none is claimed
    expect(errors[0]!.error.message).not.toMatch(/within|ms/);
  });

  it('names a host that does not resolve with the lookup error', async () => {
    const { code, errors } = await halJson(['status', '--udp', 'nosuchhost.invalid']);
    expect(code).toBe(1);
    expect(errors).toEqual([
      {
        error: expect.objectContaining({
          code: 'NOT_CONNECTED',
          message: expect.stringMatching(
            /^cannot reach the robot at nosuchhost\.invalid:4210: getaddrinfo (ENOTFOUND|EAI_AGAIN) nosuchhost\.invalid$/,
          ),
        }),
      },
    ]);
  });
});

describe('hal on a NATS device that no one serves', () => {
  let server: NatsServer;
  beforeAll(async () => {
    server = await startNatsServer();
  });
  afterAll(() => stopAllNatsServers());

  it('says no one serves the device, at once, with no timeout it did not wait for', async () => {
    const { code, errors } = await halJson([
      'status',
      '--nats',
      server.url,
      '--device',
      'nobody',
      '--connect-timeout',
      '5000',
    ]);
    expect(code).toBe(1);
    expect(errors).toEqual([
      {
        error: expect.objectContaining({
          code: 'NOT_CONNECTED',
          message:
            'device "nobody" is offline: it has not answered on "hal.v1.dev.nobody.system.capability.req": no one serves it',
        }),
      },
    ]);
  });
});

describe('hal on a WebSocket server with a token', () => {
  let sim: SimulationHAL;
  let server: HalServer;

  beforeAll(async () => {
    sim = new SimulationHAL({ clock: 'realtime' });
    await sim.initialize();
    server = await serveHal(sim, { port: 0, token: 'the-right-token-of-24-chars' });
  });
  afterAll(async () => {
    await server.close();
    await sim.cleanup();
  });

  it('reports a wrong token as the 401 the server answered, not as a dead server', async () => {
    const { code, errors } = await halJson([
      'status',
      '--ws',
      server.url,
      '--token',
      'a-wrong-token-of-24-char',
    ]);
    expect(code).toBe(1);
    expect(errors).toEqual([
      {
        error: expect.objectContaining({
          code: 'AUTH_FAILED',
          message: `${server.url} refused the connection (HTTP 401): the token is wrong (the server's --token or $HAL_SERVE_TOKEN)`,
        }),
      },
    ]);
  });

  it('reports a server that is not there as NOT_CONNECTED with the cause', async () => {
    const port = await freePort();
    const { errors } = await halJson(['status', '--ws', `ws://127.0.0.1:${port}`]);
    expect(errors[0]!.error).toMatchObject({
      code: 'NOT_CONNECTED',
      message: expect.stringContaining('ECONNREFUSED'),
    });
  });
});

describe('hal with no NATS server', () => {
  it('reports it the same way from status, test, fleet and serve, once each', async () => {
    const url = `nats://127.0.0.1:${await freePort()}`;
    const runs = await Promise.all([
      halJson(['status', '--nats', url]),
      halJson(['test', 'hal', '--nats', url]),
      halJson(['fleet', 'health', '--nats', url]),
      halJson(['serve', '--sim', '--nats', url]),
    ]);
    for (const { code, errors } of runs) {
      expect(code).toBe(1);
      expect(errors).toEqual([
        {
          error: {
            code: 'NOT_CONNECTED',
            message: `cannot reach NATS at ${url}: connection refused (is nats-server running there? see --nats or $NATS_URL)`,
            details: { servers: url },
          },
        },
      ]);
    }
  });
});

describe('hal --json', () => {
  it('writes a usage error once, as JSON only', async () => {
    const { code, errors } = await halJson(['test', '--nats', 'nats://127.0.0.1:1']);
    expect(code).toBe(2);
    expect(errors).toEqual([
      { error: { code: 'USAGE', message: "missing required argument 'suite'" } },
    ]);
  });
});
