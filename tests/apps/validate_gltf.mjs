// Runs the Khronos glTF-Validator (npm gltf-validator) on each glTF or GLB file given, with the
// files a .gltf names (buffers, images) read from beside it. Prints each file's error and warning
// counts and their messages, then a line on stderr for each file with errors, and exits 1 if any
// has; 2 on bad usage or without the validator.
//
//   node validate_gltf.mjs [--modules DIR] FILE...   (DIR: the node_modules holding the validator)
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import path from 'node:path';

const args = process.argv.slice(2);
let modules = null;
if (args[0] === '--modules') {
  modules = args[1];
  args.splice(0, 2);
}
if (args.length === 0) {
  console.error('usage: node validate_gltf.mjs [--modules DIR] FILE...');
  process.exit(2);
}
let validator;
try {
  // A require rooted in DIR finds DIR/gltf-validator; without DIR, node's own search.
  const require = createRequire(modules ? path.resolve(modules, 'x.js') : import.meta.url);
  validator = require('gltf-validator');
} catch (e) {
  console.error(`validate_gltf: cannot load gltf-validator: ${e.message.split('\n')[0]}`);
  process.exit(2);
}

const failed = [];
for (const file of args) {
  let report;
  try {
    report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
      uri: path.basename(file),
      maxIssues: 0,
      writeTimestamp: false,
      externalResourceFunction: async (uri) =>
        new Uint8Array(await readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))),
    });
  } catch (e) {
    // An unreadable file, or bytes that are neither glTF nor GLB.
    failed.push(`${file}: cannot be validated: ${String(e).split('\n')[0]}`);
    continue;
  }
  const { numErrors, numWarnings, messages } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings` +
              ` (gltf-validator ${report.validatorVersion})`);
  for (const m of messages)
    if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ` +
                                     `${m.pointer ?? ''}: ${m.message}`);
  if (numErrors > 0) failed.push(`${file}: ${numErrors} glTF-Validator errors`);
}
for (const line of failed) console.error(line);
process.exit(failed.length > 0 ? 1 : 0);
