// Runs the Khronos glTF validator (npm package gltf-validator) on each .glb file named on the
// command line: prints every issue it reports, one line each, and exits 1 if any file has an
// error (or cannot be read), else 0. The validator is found through NODE_PATH.
// Usage: NODE_PATH=PREFIX/node_modules node validate_gltf.js FILE.glb...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function main(files) {
  if (files.length === 0) {
    console.error('validate_gltf: no file named');
    return 1;
  }
  let failed = 0;
  for (const file of files) {
    let report;
    try {
      report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 0, // every issue
      });
    } catch (e) {
      console.error(`${file}: the validator failed: ${e}`);
      failed++;
      continue;
    }
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ` +
                `${i.numHints} hints (gltf-validator ${report.validatorVersion})`);
    for (const m of i.messages) {
      if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ` +
                                       `${m.pointer || ''}: ${m.message}`);
    }
    if (i.numErrors > 0) failed++;
  }
  return failed > 0 ? 1 : 0;
}

main(process.argv.slice(2)).then((code) => process.exit(code), (e) => {
  console.error(`validate_gltf: ${e}`);
  process.exit(1);
});
