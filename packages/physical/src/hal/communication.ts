import { HalError } from '@hal/types';
import type { CommunicationInterface } from '@hal/types';
import type { ScopedLogger } from '@hal/types';
import type { HalContext } from './context.js';

/**
 * The robot's LED (`set_led`) and the HAL's log, written to the injected logger (a `log` call the
 * boundary refuses records nothing and is reported there at warn level). The V1 robot has no
 * speaker: `speak` and `playSound` fail NOT_IMPLEMENTED.
 */
export function createCommunication(
  ctx: HalContext,
  robotLog: ScopedLogger,
  deviceId: string,
): CommunicationInterface {
  const b = ctx.boundary;
  return {
    speak: (text, urgency) =>
      b.call('speak', { text, urgency }, async () => {
        throw new HalError('NOT_IMPLEMENTED', 'the V1 stepper cube has no speaker');
      }),
    playSound: (soundId) =>
      b.call('playSound', { soundId }, async () => {
        throw new HalError('NOT_IMPLEMENTED', 'the V1 stepper cube has no speaker');
      }),
    setLED: (r, g, bl, pattern) =>
      b.call('setLED', { r, g, b: bl, pattern }, async (p) => {
        const reply = await ctx.command('set_led', {
          r: p.r,
          g: p.g,
          b: p.b,
          pattern: p.pattern ?? 'solid',
        });
        return { led: reply.led };
      }),
    log: (message, level) => {
      const result = b.notify('log', { message, level }, (p) => {
        robotLog[p.level ?? 'info'](p.message, { deviceId });
      });
      if (!result.success) {
        // the scoped logger swallows its own failures, so this cannot throw either
        robotLog.warn('log refused', { deviceId, code: result.code, error: result.error });
      }
    },
  };
}
