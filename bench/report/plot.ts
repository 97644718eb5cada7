// SVG line plots of how a cost grows with the work, drawn with Vega-Lite (rendered headless by
// Vega, no browser or canvas needed).
import { parse, View } from 'vega';
import { compile } from 'vega-lite';
import type { TopLevelSpec } from 'vega-lite';
import type { Point } from './figures.js';

/** Renders the points of one plot (all sharing its `plot` id) as an SVG document. */
export async function plotSvg(points: readonly Point[]): Promise<string> {
  const first = points[0];
  if (first === undefined) throw new RangeError('a plot needs at least one point');
  const spec: TopLevelSpec = {
    $schema: 'https://vega.github.io/schema/vega-lite/v6.json',
    title: first.title,
    width: 520,
    height: 300,
    background: 'white',
    data: { values: points.map(({ series, x, y }) => ({ series, x, y })) },
    mark: { type: 'line', point: true },
    encoding: {
      x: {
        field: 'x',
        type: 'quantitative',
        title: first.xLabel,
        scale: first.logX === true ? { type: 'log' } : { zero: false },
      },
      y: {
        field: 'y',
        type: 'quantitative',
        title: first.yLabel,
        scale: first.logY === true ? { type: 'log' } : { zero: false },
      },
      color: { field: 'series', type: 'nominal', title: null },
    },
  };
  const view = new View(parse(compile(spec).spec), { renderer: 'none' });
  try {
    return await view.toSVG();
  } finally {
    view.finalize();
  }
}
