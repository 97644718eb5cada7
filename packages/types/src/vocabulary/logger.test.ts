import { describe, expect, it } from 'vitest';
import { scoped, silentLogger } from './logger.js';
import type { Logger, LogLevel } from './logger.js';

describe('scoped', () => {
  it('writes each level under its namespace, with the fields', () => {
    const entries: Array<[LogLevel, string, string, Record<string, unknown> | undefined]> = [];
    const logger: Logger = {
      log: (level, namespace, message, fields) => entries.push([level, namespace, message, fields]),
    };
    const log = scoped(logger, 'hal:test');
    log.debug('d');
    log.info('i', { a: 1 });
    log.warn('w');
    log.error('e', { b: 2 });
    expect(entries).toEqual([
      ['debug', 'hal:test', 'd', undefined],
      ['info', 'hal:test', 'i', { a: 1 }],
      ['warn', 'hal:test', 'w', undefined],
      ['error', 'hal:test', 'e', { b: 2 }],
    ]);
  });

  it('ignores a logger that throws, so logging never breaks the caller', () => {
    const log = scoped(
      {
        log: () => {
          throw new Error('broken logger');
        },
      },
      'hal:test',
    );
    expect(() => log.error('x')).not.toThrow();
  });
});

describe('silentLogger', () => {
  it('accepts every level and cannot be changed', () => {
    expect(() => silentLogger.log('error', 'hal:test', 'x', { a: 1 })).not.toThrow();
    expect(Object.isFrozen(silentLogger)).toBe(true);
  });
});
