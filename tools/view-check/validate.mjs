// Runs the Khronos glTF Validator on each .glb given (files or folders, searched recursively) and prints one
// line per file: "PATH: N error(s), N warning(s)" and then each such message. Exit 1 when any file has an
// error or a warning, 2 on bad arguments. Used by the view tests (ViewGltfValidatorTests) and by hand:
//   node tools/view-check/validate.mjs docs/view
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import validator from 'gltf-validator';

function glbs(path) {
  if (statSync(path).isDirectory())
    return readdirSync(path).sort().flatMap(name => glbs(join(path, name)));
  return path.endsWith('.glb') ? [path] : [];
}

const args = process.argv.slice(2);
if (args.length === 0) {
  console.error('usage: node validate.mjs FILE_OR_FOLDER...');
  process.exit(2);
}
let failed = false;
let files = 0;
for (const file of args.flatMap(glbs)) {
  files++;
  const report = await validator.validateBytes(new Uint8Array(readFileSync(file)), { maxIssues: 100 });
  const { numErrors, numWarnings, messages } = report.issues;
  console.log(`${file}: ${numErrors} error(s), ${numWarnings} warning(s)`);
  for (const m of messages.filter(m => m.severity <= 1))
    console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer ?? ''}: ${m.message}`);
  if (numErrors > 0 || numWarnings > 0) failed = true;
}
console.log(`validated ${files} glb file(s)`);
process.exit(failed ? 1 : 0);
