import { describe, expect, it } from 'vitest';
import { HAL_CALL_TABLE } from '@hal/types';
import type { CallSpec, HardwareAbstractionLayer } from '@hal/types';
import { ServedCalls } from './served-calls.js';

const spec = (name: string): CallSpec => {
  const found = HAL_CALL_TABLE.find((entry) => entry.name === name);
  if (found === undefined) throw new Error(name);
  return found;
};

/** A HAL whose every call waits until the test lets it finish; `log` records start and end. */
function heldHal() {
  const log: string[] = [];
  const held = new Map<string, () => void>();
  const call =
    (name: string) =>
    (...args: unknown[]) => {
      log.push(`start ${name}${args.length > 0 ? ` ${args.join(',')}` : ''}`);
      return new Promise((resolve) => {
        held.set(name, () => {
          log.push(`end ${name}`);
          resolve({ success: true, mode: 'simulation', timestamp: 0 });
        });
      });
    };
  const subsystem = (names: string[]) =>
    Object.fromEntries(names.map((name) => [name, call(name)]));
  const hal = {
    locomotion: subsystem(['moveForward', 'rotate', 'stop', 'getPose']),
    safety: subsystem(['emergencyStop', 'resetEmergencyStop']),
  } as unknown as HardwareAbstractionLayer;
  const finish = async (name: string) => {
    await expect.poll(() => held.has(name)).toBe(true);
    held.get(name)?.();
    held.delete(name);
  };
  return { hal, log, finish };
}

describe('ServedCalls', () => {
  it('ordered: runs commands one at a time in arrival order, and stop, e-stop and reset at once', async () => {
    const { hal, log, finish } = heldHal();
    const served = new ServedCalls(hal, { order: 'ordered' });
    const moves = [served.run(spec('moveForward'), [10])];
    await expect.poll(() => log).toEqual(['start moveForward 10']);
    moves.push(served.run(spec('rotate'), ['left', 90]));
    const safety = [
      served.run(spec('stop'), []),
      served.run(spec('emergencyStop'), ['bumper']),
      served.run(spec('resetEmergencyStop'), []),
      served.run(spec('getPose'), []),
    ];
    await expect.poll(() => log.length).toBe(5);
    expect(log).toEqual([
      'start moveForward 10',
      'start stop',
      'start emergencyStop bumper',
      'start resetEmergencyStop',
      'start getPose',
    ]);
    expect(served.pending).toBe(2);
    for (const name of ['stop', 'emergencyStop', 'resetEmergencyStop', 'getPose']) {
      await finish(name);
    }
    await Promise.all(safety);
    expect(log).not.toContain('start rotate left,90'); // still behind the move
    await finish('moveForward');
    await finish('rotate');
    await Promise.all(moves);
    expect(log.indexOf('start rotate left,90')).toBeGreaterThan(log.indexOf('end moveForward'));
    expect(served.pending).toBe(0);
  });

  it('ordered: a command sent with priority goes ahead of the queue', async () => {
    const { hal, log, finish } = heldHal();
    const served = new ServedCalls(hal, { order: 'ordered' });
    const first = served.run(spec('moveForward'), [10]);
    await expect.poll(() => log).toEqual(['start moveForward 10']);
    const queued = served.run(spec('rotate'), ['left', 90]);
    const urgent = served.run(spec('rotate'), ['right', 5], { priority: true });
    await expect.poll(() => log).toEqual(['start moveForward 10', 'start rotate right,5']);
    await finish('rotate');
    await urgent;
    await finish('moveForward');
    await first;
    await finish('rotate');
    await queued;
    expect(log.slice(-2)).toEqual(['start rotate left,90', 'end rotate']);
  });

  it('concurrent: runs every call the moment it arrives', async () => {
    const { hal, log, finish } = heldHal();
    const served = new ServedCalls(hal, { order: 'concurrent' });
    const runs = [served.run(spec('moveForward'), [10]), served.run(spec('rotate'), ['left', 90])];
    await expect.poll(() => log).toEqual(['start moveForward 10', 'start rotate left,90']);
    await finish('moveForward');
    await finish('rotate');
    await Promise.all(runs);
  });

  it('refuses a controller-only call from a client without control, but never the safety lane', () => {
    const served = new ServedCalls(heldHal().hal, { order: 'concurrent' });
    const refused = served.refusal(spec('moveForward'), false, 'take control first');
    expect(refused).toMatchObject({
      code: 'NOT_CONTROLLER',
      details: { call: 'moveForward', hint: 'take control first' },
    });
    expect(served.refusal(spec('resetEmergencyStop'), false)?.code).toBe('NOT_CONTROLLER');
    expect(served.refusal(spec('stop'), false)).toBeUndefined();
    expect(served.refusal(spec('emergencyStop'), false)).toBeUndefined();
    expect(served.refusal(spec('getPose'), false)).toBeUndefined();
    expect(served.refusal(spec('moveForward'), true)).toBeUndefined();
  });

  it('finds the calls of its table, and no others', () => {
    const served = new ServedCalls(heldHal().hal, { order: 'concurrent' });
    expect(served.find('moveBackward')?.kind).toBe('motion');
    expect(served.find('fly')).toBeUndefined();
  });

  it('passes on what the HAL threw', async () => {
    const hal = {
      locomotion: { getPose: () => Promise.reject(new Error('no pose')) },
    } as unknown as HardwareAbstractionLayer;
    const served = new ServedCalls(hal, { order: 'ordered' });
    await expect(served.run(spec('getPose'), [])).rejects.toThrow('no pose');
  });
});
