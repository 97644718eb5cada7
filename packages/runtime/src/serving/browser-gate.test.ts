import { describe, expect, it } from 'vitest';
import { browserRefusal, hostOfHeader, isLoopback, trustedOrigin } from './browser-gate.js';

describe('isLoopback', () => {
  it('is true for localhost, 127.0.0.0/8 and ::1 only', () => {
    for (const host of ['localhost', 'LOCALHOST', '127.0.0.1', '127.1.2.3', '::1', '[::1]']) {
      expect(isLoopback(host), host).toBe(true);
    }
    for (const host of ['0.0.0.0', '10.0.0.1', '128.0.0.1', 'localhost.evil.example', '::', '']) {
      expect(isLoopback(host), host).toBe(false);
    }
  });
});

describe('hostOfHeader', () => {
  it('reads host[:port], IPv6 in brackets, and nothing else', () => {
    expect(hostOfHeader('127.0.0.1:8765')).toBe('127.0.0.1');
    expect(hostOfHeader('[::1]:80')).toBe('::1');
    expect(hostOfHeader('Example.COM')).toBe('example.com');
    for (const header of [undefined, '', 'a b', 'user@localhost', 'localhost/path']) {
      expect(hostOfHeader(header), String(header)).toBeUndefined();
    }
  });
});

describe('trustedOrigin', () => {
  it('normalises an origin as browsers send it', () => {
    expect(trustedOrigin('https://App.Example')).toBe('https://app.example');
    expect(trustedOrigin('https://app.example:443/')).toBe('https://app.example');
    expect(trustedOrigin('http://192.168.1.20:5173')).toBe('http://192.168.1.20:5173');
  });

  it('refuses anything else with INVALID_PARAMETER naming the value', () => {
    for (const value of [
      'app.example',
      'localhost:5173',
      'https://app.example/page',
      'https://app.example/?q',
      'https://user@app.example',
      'ftp://app.example',
      'null',
      '*',
      '',
    ]) {
      expect(() => trustedOrigin(value), value).toThrow(
        expect.objectContaining({
          code: 'INVALID_PARAMETER',
          details: expect.objectContaining({ received: value }),
        }),
      );
    }
  });
});

describe('browserRefusal', () => {
  const host = '127.0.0.1:8765';

  it('lets in a program (no Origin) and pages served from this machine', () => {
    expect(browserRefusal({ host })).toBeUndefined();
    for (const origin of ['http://localhost:5173', 'http://127.0.0.1', 'https://[::1]:8443']) {
      expect(browserRefusal({ host, origin }), origin).toBeUndefined();
    }
  });

  it('refuses a page from another site, an opaque origin and an unreadable one', () => {
    for (const origin of ['http://evil.example', 'null', 'http://localhost.evil.example', '%']) {
      expect(browserRefusal({ host, origin }), origin).toMatchObject({
        header: 'origin',
        value: origin,
      });
    }
  });

  it('lets in a trusted origin, compared as browsers send it', () => {
    const allowed = new Set([trustedOrigin('https://app.example')]);
    expect(browserRefusal({ host, origin: 'https://app.example' }, allowed)).toBeUndefined();
    expect(browserRefusal({ host, origin: 'https://app.example:444' }, allowed)).toMatchObject({
      header: 'origin',
    });
  });

  it('refuses a Host that is not a loopback name (DNS rebinding), or none, before the Origin', () => {
    expect(browserRefusal({ host: 'rebound.evil.example:8765' })).toMatchObject({
      header: 'host',
      reason: expect.stringMatching(/not a loopback name/),
    });
    expect(
      browserRefusal(
        { host: 'app.example', origin: 'https://app.example' },
        new Set(['https://app.example']),
      ),
    ).toMatchObject({ header: 'host' });
    expect(browserRefusal({})).toMatchObject({
      header: 'host',
      reason: 'the request names no Host',
    });
  });
});
