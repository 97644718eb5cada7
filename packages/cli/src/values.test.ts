import { describe, expect, it } from 'vitest';
import { CliError } from './cli-error.js';
import {
  angleArg,
  distanceArg,
  hexKeyArg,
  hostPortArg,
  hostPortText,
  integerArg,
  numberArg,
  portArg,
  positiveArg,
  readQuantity,
  urlArg,
} from './values.js';
import { usageErrorLike } from './usage-error.fixture.js';

/** The one usage error every parser throws, its message naming the option. */
const usage = usageErrorLike;

describe('integerArg', () => {
  const port = integerArg('--port', 0, 65_535);
  const offset = integerArg('--offset', -10, 10);

  it('reads decimal integers within the range, a minus where the range has negatives', () => {
    expect(port('0')).toBe(0);
    expect(port('65535')).toBe(65_535);
    expect(offset('-10')).toBe(-10);
  });

  it('refuses what is not written as a decimal integer, or is out of range, naming the option', () => {
    for (const value of ['', ' 5', '5 ', '1e3', '0x10', '2.0', '+1', 'NaN', '65536', '-1']) {
      expect(() => port(value), value).toThrow(CliError);
      expect(() => port(value), value).toThrow(
        usage(`"--port" must be an integer in 0..65535, got "${value}"`),
      );
    }
    expect(() => offset('11')).toThrow('"--offset" must be an integer in -10..10, got "11"');
    expect(() => integerArg('--n', 0, 1e300)('99999999999999999999')).toThrow(CliError);
  });
});

describe('numberArg and positiveArg', () => {
  it('read decimal numbers within the range, the unit named in the message', () => {
    const loss = numberArg('--loss', { min: 0, max: 0.9 });
    expect(loss('0')).toBe(0);
    expect(loss('.5')).toBe(0.5);
    expect(loss('9e-1')).toBe(0.9);
    expect(() => loss('0.95')).toThrow(usage('"--loss" must be a number in 0..0.9, got "0.95"'));
    const latency = numberArg('--latency', { min: 0, max: 10_000 }, 'ms');
    expect(() => latency('-1')).toThrow(
      usage('"--latency" must be a number in 0..10000 ms, got "-1"'),
    );
    const scale = numberArg('--time-scale', { min: 0, aboveMin: true, max: 1000 });
    expect(() => scale('0')).toThrow(
      usage('"--time-scale" must be a number in (0, 1000], got "0"'),
    );
    expect(positiveArg('--max-time')('2.5')).toBe(2.5);
    expect(() => positiveArg('--max-time', 's')('0')).toThrow(
      usage('"--max-time" must be a number > 0 s, got "0"'),
    );
  });

  it('refuse what Number() would take but is no decimal number', () => {
    const any = numberArg('--x');
    for (const value of ['', ' ', '0x10', 'NaN', 'Infinity', '12abc', '1,5', '1e999']) {
      expect(() => any(value), value).toThrow(usage(`"--x" must be a number, got "${value}"`));
    }
  });
});

describe('distances and angles', () => {
  it('read a bare number as metres or degrees, and a number with its unit', () => {
    expect(readQuantity('0.05', 'distance')).toBe(0.05);
    expect(readQuantity('30cm', 'distance')).toBe(0.3);
    expect(readQuantity('7cm', 'distance')).toBe(0.07);
    expect(readQuantity('0.3m', 'distance')).toBe(0.3);
    expect(readQuantity('300 mm', 'distance')).toBe(0.3);
    expect(readQuantity('-5cm', 'distance')).toBe(-0.05);
    expect(readQuantity('90', 'angle')).toBe(90);
    expect(readQuantity('90deg', 'angle')).toBe(90);
    expect(readQuantity('90°', 'angle')).toBe(90);
    expect(readQuantity(`${Math.PI}rad`, 'angle')).toBeCloseTo(180, 9);
  });

  it('refuse a unit of the other kind, an unknown unit, or no number', () => {
    for (const [text, kind] of [
      ['30deg', 'distance'],
      ['30cm', 'angle'],
      ['30 furlongs', 'distance'],
      ['cm', 'distance'],
      ['', 'distance'],
      ['1e3e', 'angle'],
    ] as const) {
      expect(readQuantity(text, kind), `${text} as ${kind}`).toBeUndefined();
    }
    expect(() => distanceArg('--spacing')('far')).toThrow(
      usage('"--spacing" must be a distance: metres, or with a unit: 0.3m, 30cm, 300mm; got "far"'),
    );
    expect(() => distanceArg('--spacing', { min: 0, aboveMin: true })('0cm')).toThrow(
      usage('"--spacing" must be a distance > 0 m, got "0cm"'),
    );
    expect(angleArg('angle')('1.5rad')).toBeCloseTo(85.944, 3);
    expect(() => angleArg('angle')('90cm')).toThrow(usage(/degrees, or with a unit: 90deg/));
  });
});

describe('ports and HOST[:PORT]', () => {
  it('reads a port, 0 only where any free port is meant', () => {
    expect(portArg('--port', { anyFree: true })('0')).toBe(0);
    expect(() => portArg('--port')('0')).toThrow(usage(/"--port" must be an integer in 1..65535/));
    expect(() => portArg('--port', { anyFree: true })('99999')).toThrow(
      usage('"--port" must be an integer in 0..65535, got "99999"'),
    );
  });

  it('reads a name or IPv4 address with an optional port, and IPv6 in brackets or bare', () => {
    const udp = hostPortArg('--udp');
    expect(udp('cube.local')).toEqual({ host: 'cube.local', port: 4210 });
    expect(udp('10.0.0.5:4211')).toEqual({ host: '10.0.0.5', port: 4211 });
    expect(udp('[::1]:4300')).toEqual({ host: '::1', port: 4300 });
    expect(udp('[fe80::1]')).toEqual({ host: 'fe80::1', port: 4210 });
    expect(udp('::1')).toEqual({ host: '::1', port: 4210 });
    expect(hostPortText({ host: '::1', port: 4300 })).toBe('[::1]:4300');
    expect(hostPortText({ host: '10.0.0.5', port: 1 })).toBe('10.0.0.5:1');
  });

  it('refuses a port out of range, a second colon, and brackets round no IPv6 address', () => {
    for (const value of [
      '',
      'a:b',
      'a:b:c',
      'host:0',
      'host:65536',
      '[host]:1',
      '[::1]:x',
      'a b',
    ]) {
      expect(() => hostPortArg('--udp')(value), value).toThrow(
        usage(`"--udp" must be HOST, HOST:PORT or [IPV6]:PORT (port 1..65535), got "${value}"`),
      );
    }
  });
});

describe('hexKeyArg and urlArg', () => {
  it('takes 1..64 bytes of hex, and refuses anything else naming the option', () => {
    expect(hexKeyArg('--key')('00ff')).toBe('00ff');
    expect(hexKeyArg('--key')('ab'.repeat(64))).toBe('ab'.repeat(64));
    for (const value of ['', 'abc', 'zz', 'ab'.repeat(65)]) {
      expect(() => hexKeyArg('--key')(value), value).toThrow(
        usage('"--key" must be 1..64 bytes written as hex (an even number of digits)'),
      );
    }
  });

  it('takes a URL of the given schemes only', () => {
    const baseUrl = urlArg('--base-url', ['http:', 'https:']);
    expect(baseUrl('http://127.0.0.1:8080/v1')).toBe('http://127.0.0.1:8080/v1');
    for (const value of ['notaurl', 'ftp://x/v1', 'ws://x']) {
      expect(() => baseUrl(value), value).toThrow(
        usage(`"--base-url" must be a http:// or https:// URL, got "${value}"`),
      );
    }
  });
});
