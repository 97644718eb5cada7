import { describe, expect, it } from 'vitest';
import { namedObject, namedPoint } from './named-object.js';

describe('namedObject', () => {
  it('reads the colour, the kind and the distance from the words', () => {
    expect(
      namedObject('Drive to the red box and stop next to it (within 25 cm) without touching it.'),
    ).toEqual({ colour: 'red', kind: 'box', query: 'red box', withinM: 0.25 });
    expect(namedObject('Drive to the green pillar among the obstacles.')).toEqual({
      colour: 'green',
      kind: 'pillar',
      query: 'green pillar',
    });
    expect(namedObject('Go to the blue cylinder, within 0.3 m.')).toMatchObject({
      kind: 'pillar',
      withinM: 0.3,
    });
  });

  it('takes the first colour named, with the kind a word or two after it', () => {
    expect(
      namedObject(
        'Drive to the yellow box and stop within 25 cm of it. It is not the box in front of you.',
      ),
    ).toMatchObject({ colour: 'yellow', kind: 'box' });
    expect(namedObject('Find the orange wooden crate.')).toMatchObject({
      colour: 'orange',
      kind: 'box',
    });
    expect(namedObject('Find the purple thing.')).toMatchObject({
      kind: 'unknown',
      query: 'purple',
    });
  });

  it('is undefined when no colour is named', () => {
    expect(namedObject('Reach the point x = 0 m, y = 0 m.')).toBeUndefined();
    expect(namedObject('Drive to the box.')).toBeUndefined();
  });
});

describe('namedPoint', () => {
  it('reads a point given in numbers, and how near counts', () => {
    expect(
      namedPoint(
        'Reach the point x = -0.3 m, y = 0 m, which is behind the box ahead of you, within 5 cm.',
      ),
    ).toEqual({ x: -0.3, y: 0, withinM: 0.05 });
    expect(namedPoint('Find your way to its middle, the point x = 0 m, y = 0 m.')).toEqual({
      x: 0,
      y: 0,
    });
    expect(namedPoint('Drive to the red box.')).toBeUndefined();
  });
});
