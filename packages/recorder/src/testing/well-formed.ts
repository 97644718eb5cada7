import { Ajv2020 } from 'ajv/dist/2020.js';
import { expect } from 'vitest';
import type { Recording } from '../read-recording.js';

/**
 * Holds a recording read back to what every reader expects: each message valid against its
 * channel's JSON Schema, and log times that never go backwards.
 */
export function expectWellFormed(recording: Recording): void {
  const ajv = new Ajv2020({ strict: false });
  const validators = new Map(
    [...recording.channels].map(([topic, channel]) => [
      topic,
      ajv.compile(channel.schema as Record<string, unknown>),
    ]),
  );
  let last = 0n;
  for (const message of recording.messages) {
    const validate = validators.get(message.topic);
    expect(validate, `a schema for ${message.topic}`).toBeDefined();
    expect(validate!(message.value), `${message.topic}: ${ajv.errorsText(validate!.errors)}`).toBe(
      true,
    );
    expect(message.logTime >= last, `log time of a ${message.topic} message`).toBe(true);
    last = message.logTime;
  }
}
