import type { CommunicationInterface, HalBoundary, RobotPort } from '@hal/types';

/** How many `log` messages the HAL keeps. */
export const KEPT_LOGS = 1000;

/**
 * The LED (`set_led`), the speaker where the robot has one (else NOT_IMPLEMENTED), and the HAL's
 * log: kept (the last {@link KEPT_LOGS} messages, oldest first) and recorded where the port's world
 * keeps it. A `log` call the boundary refuses records nothing and is reported at warn level.
 */
export function createCommunication(
  b: HalBoundary,
  port: RobotPort,
  logs: string[],
): CommunicationInterface {
  const speaker = () => {
    if (port.speaker === undefined) throw port.lacks('speaker');
    return port.speaker;
  };
  return {
    speak: (text, urgency) =>
      b.call('speak', { text, urgency }, async (p) => {
        await speaker().speak(p.text, p.urgency ?? 'info');
        return { spoken: p.text };
      }),
    playSound: (soundId) =>
      b.call('playSound', { soundId }, async (p) => {
        await speaker().playSound(p.soundId);
        return { soundId: p.soundId };
      }),
    setLED: (r, g, bl, pattern) =>
      b.call('setLED', { r, g, b: bl, pattern }, async (p) => ({
        led: await port.setLed({ r: p.r, g: p.g, b: p.b, pattern: p.pattern ?? 'solid' }),
      })),
    log: (message, level) => {
      const result = b.notify('log', { message, level }, (p) => {
        logs.push(p.message);
        if (logs.length > KEPT_LOGS) logs.shift();
        port.log(p.message, p.level ?? 'info');
      });
      if (!result.success) port.logRefused({ code: result.code, error: result.error });
    },
  };
}
