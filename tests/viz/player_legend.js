// node tests/viz/player_legend.js PLAYER_JS: runs player.js's drawPlot on a recording canvas and
// checks that a legend of many series (the Wang 2009 objective plot's dozen terms) stays inside
// the plot, in columns, while a short legend keeps its single column at the top left. Exit 0 if
// so; otherwise a FAIL line and exit 1. Run by tests/viz/player_assets.cpp where node exists.
'use strict';
const fs = require('fs');
const src = fs.readFileSync(process.argv[2], 'utf8');
function grab(name) {  // a top-level function's source, by brace matching
  const i = src.indexOf('function ' + name + '(');
  if (i < 0) throw new Error('player.js has no function ' + name);
  for (let k = src.indexOf('{', i), depth = 0; k < src.length; k++) {
    if (src[k] === '{') depth++;
    else if (src[k] === '}' && --depth === 0) return src.slice(i, k + 1);
  }
  throw new Error('unbalanced braces in ' + name);
}
const W = 420, H = 150, texts = [];
const noop = () => {};
const ctx = {
  measureText: (t) => ({ width: 5.5 * t.length }),
  fillText: (t, x, y) => texts.push({ t, x, y }),
};
for (const f of ['save', 'restore', 'beginPath', 'moveTo', 'lineTo', 'stroke', 'strokeRect',
                 'fillRect', 'rect', 'clip', 'translate', 'rotate', 'arc', 'fill'])
  ctx[f] = noop;
const setupCanvas = () => ({ ctx, W, H });
const niceTicks = eval('(' + grab('niceTicks') + ')');
const fmt = eval('(' + grab('fmt') + ')');
const drawPlot = eval('(' + grab('drawPlot') + ')');
let failed = false;
function legendOf(n, name) {
  texts.length = 0;
  const series = [];
  for (let i = 0; i < n; i++)
    series.push({ colour: '#000', segs: [[[0, 1], [i, i + 1]]], legend: name + i });
  drawPlot({}, 'time (s)', 'value', 0, 1, series, { x: 0.5 }, '');
  return texts.filter((e) => e.t.startsWith(name));
}
function check(ok, what) {
  if (!ok) { console.log('FAIL: ' + what); failed = true; }
}
const many = legendOf(14, 'E_term_with_a_long_name_');
const bottom = H - 30;  // drawPlot's B = 30
check(many.length === 14, '14 legend entries drawn, got ' + many.length);
check(many.every((e) => e.y <= bottom && e.x + 5.5 * e.t.length <= W),
      'every entry inside the plot: ' + JSON.stringify(many.map((e) => [e.x, e.y])));
check(new Set(many.map((e) => e.x)).size >= 2, 'more than one column');
const few = legendOf(3, 'q');
check(few.length === 3 && few.every((e) => e.x === few[0].x), 'a short legend is one column');
check(few.length === 3 && few[0].y < few[1].y && few[1].y < few[2].y, 'top to bottom');
process.exit(failed ? 1 : 0);
