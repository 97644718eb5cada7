import { CAPABILITIES, HalError, scoped } from '@hal/types';
import type { CommunicationInterface, Logger } from '@hal/types';
import type { HalContext } from './context.js';

/** How many `log` messages the HAL keeps. */
const KEPT_LOGS = 1000;

/**
 * The simulated robot's communication: `setLED` lights the robot's LED; `log`, and `speak` and
 * `playSound` with a speaker, emit `communication` events for a UI. `log` keeps the last
 * messages in `logs` (oldest first) and writes to `logger`, never the console; a `log` call the
 * boundary refuses records nothing and is reported to `logger` at warn level.
 */
export function createCommunication(
  ctx: HalContext,
  logs: string[],
  logger: Logger,
): CommunicationInterface {
  const log = scoped(logger, 'hal:simulation');
  const b = ctx.boundary;
  const requireSpeaker = (capability: string) => {
    if (!ctx.features.speaker) {
      throw new HalError('NOT_IMPLEMENTED', 'the simulated robot has no speaker', {
        details: { capability },
      });
    }
  };
  return {
    speak: (text, urgency) =>
      b.call('speak', { text, urgency }, async (p) => {
        requireSpeaker(CAPABILITIES.speaker);
        ctx.events.emit('communication', {
          type: 'speak',
          text: p.text,
          urgency: p.urgency ?? 'info',
        });
        return { spoken: p.text };
      }),
    playSound: (soundId) =>
      b.call('playSound', { soundId }, async (p) => {
        requireSpeaker(CAPABILITIES.sound);
        ctx.events.emit('communication', { type: 'sound', soundId: p.soundId });
        return { soundId: p.soundId };
      }),
    setLED: (r, g, bl, pattern) =>
      b.call('setLED', { r, g, b: bl, pattern }, async (p) => {
        const led = { r: p.r, g: p.g, b: p.b, pattern: p.pattern ?? 'solid' } as const;
        ctx.robot().setLed(led);
        ctx.events.emit('communication', { type: 'led', ...led });
        return { led };
      }),
    log: (message, level) => {
      const result = b.notify('log', { message, level }, (p) => {
        const at = p.level ?? 'info';
        logs.push(p.message);
        if (logs.length > KEPT_LOGS) logs.shift();
        log[at](p.message);
        ctx.events.emit('communication', {
          type: 'log',
          message: p.message,
          level: at,
          atMs: ctx.world.nowUs / 1000,
        });
      });
      if (!result.success) {
        // scoped() swallows a broken logger's throw: log() never throws
        log.warn(`log refused: ${result.error ?? result.code ?? 'unknown reason'}`);
      }
    },
  };
}
