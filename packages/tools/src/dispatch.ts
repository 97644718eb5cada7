import type { CallName, HardwareAbstractionLayer } from '@hal/types';

type Args = Record<string, unknown>;

/* The arguments here have passed the call's schema, so the casts only restore their types. */
const n = (a: Args, key: string) => a[key] as number;
const optN = (a: Args, key: string) => a[key] as number | undefined;

/** Runs one HAL call with validated arguments; answers its HALToolResult or value. */
export function dispatch(hal: HardwareAbstractionLayer, call: CallName, a: Args): Promise<unknown> {
  const { locomotion: loco, vision, communication: comm, safety } = hal;
  switch (call) {
    case 'moveForward':
      return loco.moveForward(n(a, 'distanceCm'));
    case 'moveBackward':
      return loco.moveBackward(n(a, 'distanceCm'));
    case 'rotate':
      return loco.rotate(a['direction'] as 'left' | 'right', n(a, 'degrees'));
    case 'moveTo':
      return loco.moveTo(n(a, 'x'), n(a, 'y'), n(a, 'z'), optN(a, 'speed'));
    case 'drive':
      return loco.drive(n(a, 'left'), n(a, 'right'), optN(a, 'durationMs'));
    case 'stop':
      return loco.stop();
    case 'getPose':
      return loco.getPose();
    case 'captureFrame':
      return vision.captureFrame();
    case 'scan':
      return vision.scan(a['mode'] as 'full' | 'targeted' | 'quick' | undefined);
    case 'getDistanceSensors':
      return vision.getDistanceSensors();
    case 'getLineSensors':
      return vision.getLineSensors();
    case 'getIMU':
      return vision.getIMU();
    case 'speak':
      return comm.speak(a['text'] as string, a['urgency'] as 'info' | 'warning' | 'alert');
    case 'setLED':
      return comm.setLED(
        n(a, 'r'),
        n(a, 'g'),
        n(a, 'b'),
        a['pattern'] as 'solid' | 'blink' | 'pulse' | undefined,
      );
    case 'playSound':
      return comm.playSound(a['soundId'] as string);
    case 'log':
      comm.log(a['message'] as string, a['level'] as 'debug' | 'info' | 'warn' | 'error');
      return Promise.resolve({ logged: true });
    case 'emergencyStop':
      return safety.emergencyStop(a['reason'] as string | undefined);
    case 'resetEmergencyStop':
      return safety.resetEmergencyStop();
    case 'getSafetyStatus':
      return Promise.resolve(safety.getSafetyStatus());
    case 'isEmergencyStopped':
      return Promise.resolve({ emergencyStopped: safety.isEmergencyStopped() });
  }
}
