// The JavaScript API's step in Node on a control dump: the median over REPEATS replays of the time
// per fragment and step (tests/web/control_dump.mjs), printed as tests/control/replay.c --time
// prints it, for scripts/web_bench.sh.
//
//   node bench/web/api_bench.mjs PACKAGE_DIR DUMP REPEATS [--floats]
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { readControlDump, timeControlDump } from '../../tests/web/control_dump.mjs';

const [packageDir, dumpPath, repeatsText, floats] = process.argv.slice(2);
const repeats = Number(repeatsText);
if (!dumpPath || !(repeats > 0)) throw new Error('usage: api_bench.mjs PACKAGE_DIR DUMP REPEATS [--floats]');
const api = await import(pathToFileURL(path.resolve(packageDir, 'fragsim.mjs')).href);
const fragsim = await api.default();
const bytes = readFileSync(dumpPath);
const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
const dump = readControlDump(buffer, fragsim, floats === '--floats' ? Float32Array : Float64Array);
const ns = timeControlDump(fragsim, dump, repeats);
console.log(`replay: time: ${ns.toFixed(1)} ns per fragment and step, the median of ${repeats} replays`);
