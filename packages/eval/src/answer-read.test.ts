import { describe, expect, it } from 'vitest';
import { readAnswer } from './answer-read.js';
import type { Question } from './answer-read.js';

/** Realistic model answers and what each commits to (undefined: nothing, or a hedge). */
const CASES: [Question, string, string | undefined][] = [
  ['colour-ahead', "It's red.", 'red'],
  ['colour-ahead', 'Red', 'red'],
  ['colour-ahead', 'The object straight ahead is GREEN.', 'green'],
  ['colour-ahead', 'There is a red box ahead and a blue pillar to the left', 'red'],
  ['colour-ahead', 'I see a blue pillar to the left and a yellow box straight ahead.', 'yellow'],
  ['colour-ahead', 'The box in front of me is purple; there is nothing else.', 'purple'],
  ['colour-ahead', "It isn't blue, it's orange.", 'orange'],
  ['colour-ahead', 'Either red or blue', undefined],
  ['colour-ahead', 'Maybe red, maybe green.', undefined],
  ['colour-ahead', 'red/blue', undefined],
  ['colour-ahead', 'No, I cannot see anything', undefined],
  ['colour-ahead', 'I could not tell.', undefined],
  ['count-boxes', 'I count 3 boxes and 2 pillars', '3'],
  ['count-boxes', 'There are 2 pillars and 4 boxes.', '4'],
  ['count-boxes', 'Three boxes.', '3'],
  ['count-boxes', '5', '5'],
  ['count-boxes', 'In total 5 objects: 3 boxes and 2 pillars.', '3'],
  ['count-boxes', 'I see red box 1, blue box 2 and yellow box 3, so 3 boxes in all.', '3'],
  ['count-boxes', 'The number of boxes is 2.', '2'],
  ['count-boxes', 'There are 2 small boxes, 1.5 m apart.', '2'],
  ['count-boxes', 'I see no boxes.', '0'],
  ['count-boxes', '3 or 4 boxes', undefined],
  ['count-boxes', 'Probably 2, possibly 3.', undefined],
  ['count-boxes', 'No, I cannot see anything', undefined],
  ['open-side', 'The left is open; the right is blocked', 'left'],
  ['open-side', 'The right is blocked, the left is open.', 'left'],
  ['open-side', 'Right.', 'right'],
  ['open-side', 'left', 'left'],
  ['open-side', 'There is a wall on my left, so the right side is clear.', 'right'],
  ['open-side', 'A box blocks the right.', 'left'],
  ['open-side', 'The left side is not open.', 'right'],
  ['open-side', 'There is no wall on the right.', 'right'],
  ['open-side', 'Open side: left', 'left'],
  ['open-side', 'Left or right, I cannot tell.', undefined],
  ['open-side', 'No, I cannot see anything', undefined],
  ['colour-of', 'The box I passed was blue.', 'blue'],
  ['colour-of', 'It was not red: it was green.', 'green'],
  ['colour-of', 'Yellow, I think.', 'yellow'],
  ['colour-of', 'Red or orange.', undefined],
  ['colour-of', 'I did not see it.', undefined],
  ['count-pillars', 'I saw 3 pillars in the first room.', '3'],
  ['count-pillars', 'There were 2 boxes and 4 pillars.', '4'],
  ['count-pillars', 'Two cylinders.', '2'],
  ['count-pillars', 'I passed pillar 2 and pillar 3, so 2 pillars in all.', '2'],
  ['count-pillars', 'No pillars.', '0'],
  ['count-pillars', 'Maybe 2, maybe 3 pillars.', undefined],
];

describe('reading a perception answer', () => {
  it.each(CASES)('%s: %j commits to %j', (question, answer, expected) => {
    expect(readAnswer(answer, question)).toBe(expected);
  });
});
