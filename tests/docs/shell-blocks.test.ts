import { spawnSync } from 'node:child_process';
import { describe, expect, it } from 'vitest';
import { blockPorts, blockScript } from './block-script.js';
import { longRunning } from './long-running.js';
import { commandLines, shellBlocks } from './shell-blocks.js';

const doc = [
  '# A guide', // 1
  '', // 2
  '```sh', // 3
  'pnpm hal status --sim', // 4
  '```', // 5
  '<!-- not run: needs the robot on the network -->', // 6
  '```bash', // 7
  'hal status --udp 192.168.4.1', // 8
  '```', // 9
  '<!-- not run: too far away -->', // 10
  '', // 11
  '```sh', // 12
  'echo far', // 13
  '```', // 14
  '```ts', // 15
  'const x = 1;', // 16
  '```', // 17
  '<!-- not run: -->', // 18
  '```console', // 19
  '$ echo hi', // 20
  'hi', // 21
  '```', // 22
  '````markdown', // 23
  '<!-- not run: an example inside a fence -->', // 24
  '```sh', // 25
  '```', // 26
  '````', // 27
  'Prose may quote `<!-- not run: REASON -->` in backticks.', // 28
].join('\n');

describe('shellBlocks', () => {
  const { blocks, misplaced } = shellBlocks(doc, 'docs/guide.md');

  it('finds the sh, bash and console blocks with the line of their fence, and no other language', () => {
    expect(blocks.map((b) => [b.line, b.language])).toEqual([
      [3, 'sh'],
      [7, 'bash'],
      [12, 'sh'],
      [19, 'console'],
    ]);
  });

  it('takes the marker on the line right before a fence as the reason the block is not run', () => {
    expect(blocks.map((b) => b.notRun)).toEqual([
      undefined,
      'needs the robot on the network',
      undefined,
      undefined,
    ]);
  });

  it('reports a marker that is not right before a fence, or gives no reason, and none in examples', () => {
    expect(misplaced.map((m) => m.line)).toEqual([10, 18]);
  });
});

describe('commandLines', () => {
  it('joins continued lines and drops comments and blank lines', () => {
    expect(
      commandLines({ language: 'sh', text: 'A=1 \\\n  echo $A\n# a comment\n\necho two # two' }),
    ).toEqual(['A=1 \\\n  echo $A', 'echo two # two']);
  });

  it("takes only a console block's prompted lines, not the output shown", () => {
    expect(commandLines({ language: 'console', text: '$ echo hi\nhi\n$ ls' })).toEqual([
      'echo hi',
      'ls',
    ]);
  });
});

describe('longRunning', () => {
  it('knows the servers, teleop and the demo, with or without pnpm and variables before them', () => {
    expect(longRunning('pnpm hal serve --sim --nats nats://127.0.0.1:4222')?.name).toBe(
      'hal serve',
    );
    expect(longRunning('HAL_KEY=00 hal serve --udp 192.168.4.1')?.name).toBe('hal serve');
    expect(longRunning('hal teleop --sim')?.tty).toBe(true);
    expect(longRunning('pnpm hal mcp --http')?.name).toBe('hal mcp');
    expect(longRunning('pnpm start    # the demo')?.name).toBe('the browser demo (vite)');
    expect(longRunning('hal status --ws ws://127.0.0.1:8765 --watch')?.name).toBe(
      'hal status --watch',
    );
  });

  it('leaves commands that end by themselves alone', () => {
    expect(longRunning('pnpm hal status --sim')).toBeUndefined();
    expect(longRunning('pnpm test')).toBeUndefined();
    expect(longRunning('bash scripts/setup.sh && pnpm start')).toBeUndefined();
    expect(
      longRunning('firmware/build/cube-emulator --udp-port 4210 &   # in the background'),
    ).toBeUndefined();
    expect(longRunning("'/b'/cube-emulator --udp-port 4210")?.name).toBe('cube-emulator');
  });
});

describe('blockPorts', () => {
  it('finds the ports a block names and the defaults of what it starts', () => {
    expect(
      blockPorts({
        language: 'sh',
        text: 'hal serve --sim --ws-port 8765 --nats nats://127.0.0.1:4222\npnpm hal mcp',
      }).sort(),
    ).toEqual([3333, 4222, 8765]);
  });
});

describe('blockScript', () => {
  const run = (text: string) =>
    spawnSync('bash', ['-c', blockScript({ language: 'sh', text })], {
      encoding: 'utf8',
      timeout: 20_000,
    });

  it('runs the commands in order and stops at the first that fails', () => {
    const ok = run('echo one\necho two');
    expect([ok.status, ok.stdout]).toEqual([0, 'one\ntwo\n']);
    const failed = run('echo one\nfalse\necho never');
    expect(failed.status).not.toBe(0);
    expect(failed.stdout).toBe('one\n');
  });

  it('stops what the block put in the background when it ends', () => {
    const started = run('sleep 30 &\necho $!');
    expect(started.status).toBe(0);
    const pid = Number(started.stdout.trim());
    expect(pid).toBeGreaterThan(0);
    expect(() => process.kill(pid, 0)).toThrow(); // no such process any more
  });

  it('points firmware/build/cube-emulator at CUBE_BUILD_DIR when that is set', () => {
    const script = blockScript(
      { language: 'sh', text: 'ls -l firmware/build/cube-emulator' },
      { buildDir: '/b' },
    );
    expect(script).toContain("ls -l '/b'/cube-emulator");
  });

  it("starts a nats-server on 4222 first for a block that names the docs' NATS URL and starts none", () => {
    const needs = blockScript(
      { language: 'sh', text: 'hal status --device sim-1 --nats nats://127.0.0.1:4222' },
      { natsServer: '/usr/sbin/nats-server' },
    );
    const lines = needs.split('\n');
    const start = lines.findIndex(
      (l) => l.includes('/usr/sbin/nats-server') && l.includes(' -a 127.0.0.1 -p 4222'),
    );
    const status = lines.findIndex((l) => l.startsWith('hal status'));
    expect(start).toBeGreaterThan(0);
    expect(lines[start]).toMatch(/^__doc_start 'nats-server' 'Server is ready' 0 /);
    expect(status).toBeGreaterThan(start);
    const own = blockScript(
      {
        language: 'sh',
        text: 'nats-server -a 127.0.0.1 &\nhal status --nats nats://127.0.0.1:4222',
      },
      { natsServer: '/usr/sbin/nats-server' },
    );
    expect(own).not.toContain('/usr/sbin/nats-server');
    expect(blockScript({ language: 'sh', text: 'hal status --sim' })).not.toContain('nats-server');
  });
});
