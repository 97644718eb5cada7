import type { CommunicationInterface, LocomotionInterface, VisionInterface } from '@hal/types';
import type { HybridContext } from './context.js';

/**
 * Every motion runs on both robots; the pose is the physical robot's. A `moveTo` target is a point
 * of the physical robot's frame, carried into the twin's frame for the twin.
 */
export function createLocomotion(ctx: HybridContext): LocomotionInterface {
  const { physical: p, twin: t } = ctx;
  return {
    drive: (left, right, durationMs) =>
      ctx.run(
        'drive',
        { left, right, durationMs },
        (a) => p.locomotion.drive(a.left, a.right, a.durationMs),
        (a) => t.locomotion.drive(a.left, a.right, a.durationMs),
      ),
    moveTo: (x, y, z, speed) =>
      ctx.run(
        'moveTo',
        { x, y, z, speed },
        (a) => p.locomotion.moveTo(a.x, a.y, a.z, a.speed),
        (a) => {
          const target = ctx.twinPoint(a.x, a.y);
          return t.locomotion.moveTo(target.x, target.y, a.z, a.speed);
        },
      ),
    rotate: (direction, degrees) =>
      ctx.run(
        'rotate',
        { direction, degrees },
        (a) => p.locomotion.rotate(a.direction, a.degrees),
        (a) => t.locomotion.rotate(a.direction, a.degrees),
      ),
    moveForward: (distanceCm) =>
      ctx.run(
        'moveForward',
        { distanceCm },
        (a) => p.locomotion.moveForward(a.distanceCm),
        (a) => t.locomotion.moveForward(a.distanceCm),
      ),
    moveBackward: (distanceCm) =>
      ctx.run(
        'moveBackward',
        { distanceCm },
        (a) => p.locomotion.moveBackward(a.distanceCm),
        (a) => t.locomotion.moveBackward(a.distanceCm),
      ),
    stop: () =>
      ctx.run(
        'stop',
        {},
        () => p.locomotion.stop(),
        () => t.locomotion.stop(),
      ),
    getPose: () => ctx.read('getPose', {}, () => p.locomotion.getPose()),
  };
}

/**
 * Sensing is the physical robot's alone: what it lacks fails as it fails there (NOT_IMPLEMENTED),
 * never filled in from the twin's simulated sensors.
 */
export function createVision(ctx: HybridContext): VisionInterface {
  const v = ctx.physical.vision;
  return {
    captureFrame: () => ctx.read('captureFrame', {}, () => v.captureFrame()),
    scan: (mode) => ctx.read('scan', { mode }, (a) => v.scan(a.mode)),
    getDistanceSensors: () => ctx.read('getDistanceSensors', {}, () => v.getDistanceSensors()),
    getLineSensors: () => ctx.read('getLineSensors', {}, () => v.getLineSensors()),
    getIMU: () => ctx.read('getIMU', {}, () => v.getIMU()),
  };
}

/** Speech, sound and logs go to the physical robot; the LED to both, so a twin's UI shows it. */
export function createCommunication(ctx: HybridContext): CommunicationInterface {
  const { physical: p, twin: t } = ctx;
  return {
    speak: (text, urgency) =>
      ctx.run('speak', { text, urgency }, (a) => p.communication.speak(a.text, a.urgency)),
    setLED: (r, g, b, pattern) =>
      ctx.run(
        'setLED',
        { r, g, b, pattern },
        (a) => p.communication.setLED(a.r, a.g, a.b, a.pattern),
        (a) => t.communication.setLED(a.r, a.g, a.b, a.pattern),
      ),
    playSound: (soundId) =>
      ctx.run('playSound', { soundId }, (a) => p.communication.playSound(a.soundId)),
    log: (message, level) =>
      ctx.notify('log', { message, level }, (a) => p.communication.log(a.message, a.level)),
  };
}
