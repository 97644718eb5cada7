import { describe, expect, it } from 'vitest';
import { V1_ROBOT } from '../robot-config.js';
import type {
  CommunicationInterface,
  HardwareAbstractionLayer,
  LocomotionInterface,
  ManipulationInterface,
  SafetyInterface,
  VisionInterface,
} from '../interfaces.js';
import { HAL_CALL_TABLE, MOTION_CALLS, findCall, motionCall } from './call-table.js';
import type { CallName, CallSpec } from './call-table.js';
import { V1_CALL_SCHEMAS } from './calls.js';
import { forwardCalls } from './forward-calls.js';
import { argsFromObject, invokeCall } from './invoke-call.js';

/** A HAL whose every method records its name and arguments and answers them back. */
function recordingHal(): { hal: HardwareAbstractionLayer; calls: [string, unknown[]][] } {
  const calls: [string, unknown[]][] = [];
  const subsystems = forwardCalls((spec, args) => {
    calls.push([`${spec.subsystem}.${spec.method}`, args]);
    return Promise.resolve({ ran: spec.name, args });
  });
  return { hal: subsystems as unknown as HardwareAbstractionLayer, calls };
}

/** The methods of the four subsystems every HAL has. */
type SubsystemMethod =
  | keyof LocomotionInterface
  | keyof VisionInterface
  | keyof CommunicationInterface
  | keyof SafetyInterface;
type Equal<A, B> = [A] extends [B] ? ([B] extends [A] ? true : false) : false;
// checked when this compiles: the table's calls are exactly the methods of the four subsystems
const tableIsTheInterface: Equal<CallName, SubsystemMethod> = true;

describe('HAL_CALL_TABLE', () => {
  it('has every method of the four subsystems and none of the arm (see docs/architecture.md)', () => {
    expect(tableIsTheInterface).toBe(true);
    expect(HAL_CALL_TABLE.map((s) => s.subsystem)).not.toContain('manipulation');
    // the arm's own methods; its moveTo shares the name of locomotion's
    const arm: readonly Exclude<keyof ManipulationInterface, 'moveTo'>[] = [
      'grasp',
      'extend',
      'retract',
      'setPrecisionMode',
      'getPosition',
    ];
    for (const method of arm) expect(HAL_CALL_TABLE.map((s) => s.method)).not.toContain(method);
  });

  it('lists every call of the call schemas exactly once, with a unique tool name', () => {
    const names = HAL_CALL_TABLE.map((spec) => spec.name);
    expect([...names].sort()).toEqual(Object.keys(V1_CALL_SCHEMAS).sort());
    const tools = HAL_CALL_TABLE.map((spec) => spec.tool.name);
    expect(new Set(tools).size).toBe(tools.length);
  });

  it('refers to the call schemas themselves rather than copies', () => {
    for (const spec of HAL_CALL_TABLE) {
      expect(spec.paramsSchema(V1_ROBOT)).toBe(spec.paramsSchema(V1_ROBOT));
      expect(
        Object.keys((spec.paramsSchema(V1_ROBOT) as unknown as { shape: object }).shape),
      ).toEqual([...spec.params]);
    }
    expect(findCall('moveTo')?.params).toEqual(['x', 'y', 'z', 'speed']);
  });

  it('puts stop and the e-stop in the safety lane, open to every client', () => {
    const safety = HAL_CALL_TABLE.filter((spec) => spec.lane === 'safety').map((s) => s.name);
    expect(safety.sort()).toEqual(['emergencyStop', 'stop']);
    for (const name of safety) expect(findCall(name)?.controllerOnly).toBe(false);
  });

  it('derives MOTION_CALLS from the calls of kind motion', () => {
    expect([...MOTION_CALLS].sort()).toEqual(
      ['drive', 'moveBackward', 'moveForward', 'moveTo', 'rotate'].sort(),
    );
  });
});

describe('motionCall', () => {
  it('gives every call of kind motion what it does, and no other call', () => {
    for (const spec of HAL_CALL_TABLE) {
      expect(spec.motion !== undefined, spec.name).toBe(spec.kind === 'motion');
    }
    const motions = HAL_CALL_TABLE.flatMap((spec) =>
      spec.motion === undefined ? [] : [spec.motion],
    );
    expect(new Set(motions).size).toBe(motions.length);
  });

  it('finds the call that does a motion, with the parameters that motion reads', () => {
    for (const motion of ['forward', 'backward'] as const) {
      expect(motionCall(motion).params).toEqual(['distanceCm']);
      expect(motionCall(motion).kind).toBe('motion');
    }
    expect(motionCall('forward').name).not.toBe(motionCall('backward').name);
    expect(motionCall('turn').params).toEqual(['direction', 'degrees']);
    expect(motionCall('point').params).toEqual(['x', 'y', 'z', 'speed']);
  });

  it('finds a motion in an extended table, and refuses one the table lacks', () => {
    const crab: CallSpec = { ...motionCall('forward'), name: 'crabLeft', motion: 'backward' };
    expect(motionCall('backward', [crab]).name).toBe('crabLeft');
    expect(() => motionCall('turn', [crab])).toThrow(
      expect.objectContaining({ code: 'INVALID_PARAMETER' }) as unknown as Error,
    );
  });
});

describe('invokeCall', () => {
  it('calls the right method with the arguments in order', async () => {
    const { hal, calls } = recordingHal();
    await invokeCall(hal, 'setLED', [1, 2, 3, 'blink']);
    await invokeCall(hal, 'moveTo', [0.5, -0.25, 0]);
    expect(calls).toEqual([
      ['communication.setLED', [1, 2, 3, 'blink']],
      ['locomotion.moveTo', [0.5, -0.25, 0]],
    ]);
  });

  it('answers nothing for a void call', async () => {
    const { hal } = recordingHal();
    await expect(invokeCall(hal, 'log', ['hello', 'info'])).resolves.toBeUndefined();
  });

  it('rejects an unknown call with INVALID_PARAMETER, naming it', async () => {
    const { hal, calls } = recordingHal();
    await expect(invokeCall(hal, 'selfDestruct', [])).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
      message: expect.stringContaining('selfDestruct') as unknown,
    });
    expect(calls).toEqual([]);
  });

  it('rejects NOT_IMPLEMENTED when the HAL lacks the method', async () => {
    const hal = { locomotion: {} } as unknown as HardwareAbstractionLayer;
    await expect(invokeCall(hal, 'moveForward', [10])).rejects.toMatchObject({
      code: 'NOT_IMPLEMENTED',
    });
  });
});

describe('argsFromObject', () => {
  it('orders named arguments as the call takes them and drops trailing omissions', () => {
    const drive = findCall('drive');
    if (drive === undefined) throw new Error('drive is in the table');
    expect(argsFromObject(drive, { right: 20, left: 10 })).toEqual([10, 20]);
    expect(argsFromObject(drive, { right: 20, left: 10, durationMs: 500 })).toEqual([10, 20, 500]);
  });
});
