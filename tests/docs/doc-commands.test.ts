// Every shell block of README.md and docs/*.md (fences marked sh, bash, shell or console) runs as
// written, from the repository root, so a documented command cannot rot.
//
// The convention, for whoever writes docs: a block that cannot run here (it needs the robot on
// the network, a hosted model's key, a board to flash, or has a placeholder such as `sk-...` or
// `<cube-ip>` to fill in) carries an HTML comment on the line right before its fence:
//
//     <!-- not run: needs the robot on the network -->
//
// and every other block runs. The reason is listed as a test of its own, so nothing is skipped
// silently. A block that another test already runs may say so instead of running twice, but only
// by naming that test's file: `<!-- not run: covered by tests/cli/readme.test.ts -->` (the file
// must exist). Long-running commands (`pnpm start`, `hal serve`, `hal teleop`, `hal mcp`, ...; see
// long-running.ts) are started, checked for their ready line and stopped with Ctrl-C at the end of
// their block. `hal` is on PATH as docs/cli.md sets it up from a checkout (scripts/hal.js). A
// block that names nats://127.0.0.1:4222 gets a nats-server there, started with it; a block
// that runs firmware/build/cube-emulator gets $CUBE_BUILD_DIR/cube-emulator when that is set.
//
// The blocks name default ports (4222, 8765, 4210, 3333), which a machine running the README's
// services has taken. Each block runs in a network of its own (block-network.ts), where they are
// free: the test holds them on the machine's 127.0.0.1 all the while, as those services would, so
// a block that reached the machine's network would fail here. Blocks run a few at a time. (Where
// the machine gives no network namespace, they run on its network, never two at once that name
// the same port, and those ports must be free.)
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, readdirSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { natsServerPath } from '../nats/nats-server.js';
import { requireEmulator } from '../physical/emulator.js';
import { blockNetwork } from './block-network.js';
import type { BlockNetwork } from './block-network.js';
import { blockPorts, blockScript, DOCS_NATS_URL } from './block-script.js';
import type { BlockScriptOptions } from './block-script.js';
import { holdPorts, takenPorts } from './held-ports.js';
import type { HeldPorts } from './held-ports.js';
import { shellBlocks } from './shell-blocks.js';
import type { ShellBlock } from './shell-blocks.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const documents = [
  'README.md',
  ...readdirSync(join(root, 'docs'))
    .filter((name) => name.endsWith('.md'))
    .sort()
    .map((name) => `docs/${name}`),
];
const scanned = documents.map((file) => shellBlocks(readFileSync(join(root, file), 'utf8'), file));
const blocks = scanned.flatMap((s) => s.blocks);
const misplaced = scanned.flatMap((s) => s.misplaced);
const runnable = blocks.filter((b) => b.notRun === undefined);
const notRun = blocks.filter((b) => b.notRun !== undefined);

/** Seconds one block may run (long-running commands included) before it is stopped. */
const BLOCK_TIMEOUT_S = 180;
const PARALLEL = 3;

const where = (b: ShellBlock): string => `${b.file}:${b.line}`;

// --- a few blocks at a time, and one at a time per port ---
let free = PARALLEL;
const waiting: (() => void)[] = [];
async function slot(): Promise<() => void> {
  if (free === 0) await new Promise<void>((resolve) => waiting.push(resolve));
  else free -= 1;
  return () => {
    const next = waiting.shift();
    if (next === undefined) free += 1;
    else next();
  };
}
const portTails = new Map<number, Promise<void>>();
async function lockPorts(ports: number[]): Promise<() => void> {
  const releases: (() => void)[] = [];
  for (const port of [...ports].sort((a, b) => a - b)) {
    const previous = portTails.get(port) ?? Promise.resolve();
    let release!: () => void;
    const held = new Promise<void>((resolve) => (release = resolve));
    portTails.set(
      port,
      previous.then(() => held),
    );
    await previous;
    releases.push(release);
  }
  return () => releases.forEach((release) => release());
}

interface Outcome {
  code: number | null;
  output: string;
}

let binDir = '';
let network: BlockNetwork | undefined;
let held: HeldPorts | undefined;
const scriptOptions: BlockScriptOptions = { buildDir: process.env['CUBE_BUILD_DIR'] };
function runBlock(block: ShellBlock, where: BlockNetwork): Promise<Outcome> {
  const env: NodeJS.ProcessEnv = { ...process.env, PATH: `${binDir}:${process.env['PATH'] ?? ''}` };
  for (const name of Object.keys(env)) {
    if (/^(HAL_|OPENAI_)/.test(name)) delete env[name]; // the block says what it needs
  }
  env['NO_COLOR'] = '1';
  const { file, args } = where.command(blockScript(block, scriptOptions));
  return new Promise((resolve) => {
    const child = spawn(file, args, { cwd: root, env, detached: true });
    let output = '';
    child.stdout.on('data', (chunk: Buffer) => (output += chunk.toString()));
    child.stderr.on('data', (chunk: Buffer) => (output += chunk.toString()));
    const timer = setTimeout(() => {
      output += `\ndoc-test: the block did not finish within ${BLOCK_TIMEOUT_S} s. A server: add its ready line to tests/docs/long-running.ts; a command that needs a person at the keyboard: mark the block <!-- not run: REASON -->`;
      child.kill('SIGTERM'); // its EXIT trap stops what it started
      setTimeout(() => {
        if (child.pid !== undefined && child.exitCode === null) process.kill(-child.pid, 'SIGKILL');
      }, 15_000).unref();
    }, BLOCK_TIMEOUT_S * 1000);
    child.once('close', (code) => {
      clearTimeout(timer);
      resolve({ code, output });
    });
  });
}

beforeAll(async () => {
  binDir = mkdtempSync(join(tmpdir(), 'hal-doc-bin-'));
  symlinkSync(join(root, 'scripts', 'hal.js'), join(binDir, 'hal'));
  // bundle the CLI once, before blocks run `hal` side by side
  const warm = spawnSync(process.execPath, ['scripts/hal.js', '--version'], {
    cwd: root,
    encoding: 'utf8',
    timeout: 120_000,
  });
  if (warm.status !== 0) throw new Error(`scripts/hal.js --version failed: ${warm.stderr}`);
  if (runnable.some((b) => b.text.includes(DOCS_NATS_URL))) {
    scriptOptions.natsServer = natsServerPath();
  }
  network = blockNetwork();
  // The ports the blocks name, taken on the machine as its own services would take them.
  if (network.own)
    held = await holdPorts([...new Set(runnable.flatMap(blockPorts))].sort((a, b) => a - b));
  // a clear message, naming the build command, rather than a block failing on a missing file
  if (runnable.some((b) => b.text.includes('firmware/build/cube-emulator'))) requireEmulator();
}, 150_000);

afterAll(async () => {
  await held?.release();
  if (binDir !== '') rmSync(binDir, { recursive: true, force: true });
});

describe('the shell blocks of README.md and docs/*.md', () => {
  it('are found (the scan sees fences at all)', () => {
    expect(blocks.length).toBeGreaterThan(10);
    expect(runnable.length).toBeGreaterThan(5);
  });

  it('have the ports they name to themselves, whatever the machine runs', async () => {
    const ports = [...new Set(runnable.flatMap(blockPorts))].sort((a, b) => a - b);
    expect(ports).toEqual(expect.arrayContaining([4222, 8765]));
    const taken = await takenPorts(ports);
    if (network?.own === true) {
      // each block has its own loopback, while the machine's has every one of them taken
      expect(taken).toEqual(ports);
    } else {
      expect(
        taken,
        `ports taken on this machine, which gives a block no network of its own (${network?.reason ?? ''})`,
      ).toEqual([]);
    }
  });

  it('have every "not run" marker on the line right before a shell fence, with a reason', () => {
    expect(misplaced).toEqual([]);
  });

  describe.each(notRun)('$file:$line', (block) => {
    it(`is not run: ${block.notRun}`, () => {
      const reason = block.notRun ?? '';
      expect(reason.length, 'the reason says why').toBeGreaterThan(10);
      if (/\bcovered by\b/i.test(reason)) {
        const named = [...reason.matchAll(/[\w.-]+(?:\/[\w.*-]+)+/g)].map((m) => m[0]);
        expect(named, 'a "covered by" marker names the test file').not.toEqual([]);
        for (const path of named) {
          expect(existsSync(join(root, path.replace(/\/?\*.*$/, ''))), `${path} exists`).toBe(true);
        }
      }
    });
  });

  // One suite for all of them: vitest runs concurrent tests together only within a suite.
  describe('run as written', () => {
    it.concurrent.each(runnable)(
      '$file:$line',
      async (block) => {
        if (network === undefined) throw new Error('beforeAll did not finish');
        // In a network of its own a block shares no port with the others.
        const unlockPorts = network.own ? () => undefined : await lockPorts(blockPorts(block));
        const release = await slot();
        try {
          const { code, output } = await runBlock(block, network);
          const onMachine = network.own
            ? ''
            : `\n(run on this machine's network, which gives no namespace: ${network.reason ?? ''}; the ports it names must be free)`;
          expect(
            code,
            `${where(block)} failed:\n${block.text}\n--- output ---\n${output.slice(-6000)}${onMachine}`,
          ).toBe(0);
        } finally {
          release();
          unlockPorts();
        }
      },
      (BLOCK_TIMEOUT_S + 30) * 1000 * 3,
    );
  });
});
