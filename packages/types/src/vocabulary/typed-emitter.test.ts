import { describe, expect, it } from 'vitest';
import { TypedEmitter } from './typed-emitter.js';

interface Events {
  tick: number;
  name: string;
}

describe('TypedEmitter', () => {
  it('calls the listeners of an event with its payload, in the order they were added', () => {
    const emitter = new TypedEmitter<Events>();
    const seen: string[] = [];
    emitter.on('tick', (t) => seen.push(`a${t}`));
    emitter.on('tick', (t) => seen.push(`b${t}`));
    emitter.on('name', (n) => seen.push(n));
    emitter.emit('tick', 1);
    expect(seen).toEqual(['a1', 'b1']);
  });

  it('stops calling a listener once it unsubscribes', () => {
    const emitter = new TypedEmitter<Events>();
    const seen: number[] = [];
    const off = emitter.on('tick', (t) => seen.push(t));
    emitter.emit('tick', 1);
    off();
    emitter.emit('tick', 2);
    expect(seen).toEqual([1]);
    expect(emitter.has('tick')).toBe(false);
  });

  it('says whether anyone listens to an event', () => {
    const emitter = new TypedEmitter<Events>();
    expect(emitter.has('tick')).toBe(false);
    emitter.on('tick', () => undefined);
    expect(emitter.has('tick')).toBe(true);
    expect(emitter.has('name')).toBe(false);
  });

  it('still calls the other listeners and returns normally when a listener throws', () => {
    const emitter = new TypedEmitter<Events>();
    const seen: number[] = [];
    emitter.on('tick', () => {
      throw new Error('broken listener');
    });
    emitter.on('tick', (t) => seen.push(t));
    expect(() => emitter.emit('tick', 7)).not.toThrow();
    emitter.emit('tick', 8);
    expect(seen).toEqual([7, 8]);
  });

  it('hands what a listener threw, with the event, to its error handler', () => {
    const reported: Array<[string, unknown]> = [];
    const emitter = new TypedEmitter<Events>((event, error) => reported.push([event, error]));
    const thrown = new Error('broken listener');
    emitter.on('name', () => {
      throw thrown;
    });
    emitter.emit('name', 'x');
    expect(reported).toEqual([['name', thrown]]);
  });

  it('survives an error handler that throws too', () => {
    const emitter = new TypedEmitter<Events>(() => {
      throw new Error('broken handler');
    });
    const seen: number[] = [];
    emitter.on('tick', () => {
      throw new Error('broken listener');
    });
    emitter.on('tick', (t) => seen.push(t));
    expect(() => emitter.emit('tick', 1)).not.toThrow();
    expect(seen).toEqual([1]);
  });

  it('finishes the round it started when a listener unsubscribes another', () => {
    const emitter = new TypedEmitter<Events>();
    const seen: string[] = [];
    let offB: () => void = () => undefined;
    emitter.on('tick', () => {
      seen.push('a');
      offB();
    });
    offB = emitter.on('tick', () => seen.push('b'));
    emitter.emit('tick', 1);
    emitter.emit('tick', 2);
    expect(seen).toEqual(['a', 'b', 'a']);
  });
});
