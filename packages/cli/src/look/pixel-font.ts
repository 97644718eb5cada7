// A 5x7 pixel font (capitals, digits, a few signs) for labels drawn into a frame: a box's label
// is a few characters, too little to load a font library for.

/** Each glyph: 7 rows of 5 columns, `#` lit (exported for the test that checks each is 5x7). */
export const GLYPHS: Readonly<Record<string, string>> = {
  A: '.###.#...##...#######...##...##...#',
  B: '####.#...##...#####.#...##...#####.',
  C: '.###.#...##....#....#....#...#.###.',
  D: '####.#...##...##...##...##...#####.',
  E: '######....#....####.#....#....#####',
  F: '######....#....####.#....#....#....',
  G: '.###.#...##....#.####...##...#.####',
  H: '#...##...##...#######...##...##...#',
  I: '.###...#....#....#....#....#...###.',
  J: '..###...#....#....#....##..#..##...',
  K: '#...##..#.#.#..##...#.#..#..#.#...#',
  L: '#....#....#....#....#....#....#####',
  M: '#...###.###.#.##...##...##...##...#',
  N: '#...##...###..##.#.##..###...##...#',
  O: '.###.#...##...##...##...##...#.###.',
  P: '####.#...##...#####.#....#....#....',
  Q: '.###.#...##...##...##.#.##..#..##.#',
  R: '####.#...##...#####.#.#..#..#.#...#',
  S: '.####.....#.....###......#....####.',
  T: '#####..#....#....#....#....#....#..',
  U: '#...##...##...##...##...##...#.###.',
  V: '#...##...##...##...##...#.#.#...#..',
  W: '#...##...##...##.#.##.#.##.#.#.#.#.',
  X: '#...##...#.#.#...#...#.#.#...##...#',
  Y: '#...##...#.#.#...#....#....#....#..',
  Z: '#####....#...#...#...#...#....#####',
  '0': '.###.#...##..###.#.###..##...#.###.',
  '1': '..#...##....#....#....#....#...###.',
  '2': '.###.#...#....#...#...#...#...#####',
  '3': '#####...#...#.....#.....##...#.###.',
  '4': '...#...##..#.#.#..#.#####...#....#.',
  '5': '######....####.....#....##...#.###.',
  '6': '..##..#...#....####.#...##...#.###.',
  '7': '#####....#...#...#...#....#....#...',
  '8': '.###.#...##...#.###.#...##...#.###.',
  '9': '.###.#...##...#.####....#...#..##..',
  '.': '..........................##...##..',
  ',': '.....................##...#...#....',
  '-': '...............' + '.###.' + '...............',
  '+': '.......#....#..#####..#....#.......',
  '%': '##...##..#...#...#...#...#..##...##',
  '/': '.........#...#...#...#...#.........',
  '(': '...#...#...#....#....#.....#.....#.',
  ')': '.#.....#.....#....#....#...#...#...',
  ':': '.......##...##.........##...##.....',
  ' ': '.'.repeat(35),
};

/** Glyph width and height, pixels; a character takes width + 1 across. */
export const GLYPH_WIDTH = 5;
export const GLYPH_HEIGHT = 7;

/** Width of `text` drawn at `scale`, pixels. */
export function textWidth(text: string, scale = 1): number {
  return text.length === 0 ? 0 : (text.length * (GLYPH_WIDTH + 1) - 1) * scale;
}

/**
 * Calls `lit(x, y)` for every lit pixel of `text` (upper-cased; a character the font lacks is
 * drawn as a blank) with its top-left corner at (x, y), each font pixel `scale` pixels square.
 */
export function forEachTextPixel(
  text: string,
  x: number,
  y: number,
  lit: (px: number, py: number) => void,
  scale = 1,
): void {
  let left = x;
  for (const char of text.toUpperCase()) {
    const glyph = GLYPHS[char];
    if (glyph !== undefined) {
      for (let i = 0; i < GLYPH_WIDTH * GLYPH_HEIGHT; i += 1) {
        if (glyph[i] !== '#') continue;
        const gx = left + (i % GLYPH_WIDTH) * scale;
        const gy = y + Math.floor(i / GLYPH_WIDTH) * scale;
        for (let dy = 0; dy < scale; dy += 1)
          for (let dx = 0; dx < scale; dx += 1) lit(gx + dx, gy + dy);
      }
    }
    left += (GLYPH_WIDTH + 1) * scale;
  }
}
