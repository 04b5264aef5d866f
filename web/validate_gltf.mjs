// Checks glTF files with the Khronos glTF validator (npm gltf-validator, pinned in
// package.json): `node web/validate_gltf.mjs FILE_OR_FOLDER...` validates each .gltf and
// .glb file named, and those directly inside each folder named. It prints one line per
// file (its errors, warnings and infos counted) and every error found, and exits 1 when
// any file has an error, 2 when nothing was given to check or a file cannot be read.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import validator from 'gltf-validator';

function filesOf(args) {
  const files = [];
  for (const arg of args) {
    if (statSync(arg).isDirectory()) {
      for (const name of readdirSync(arg).sort()) {
        if (name.endsWith('.gltf') || name.endsWith('.glb')) files.push(join(arg, name));
      }
    } else {
      files.push(arg);
    }
  }
  return files;
}

let files;
try {
  files = filesOf(process.argv.slice(2));
} catch (e) {
  console.error(`validate_gltf: ${e.message}`);
  process.exit(2);
}
if (files.length === 0) {
  console.error('validate_gltf: no .gltf or .glb file to check');
  process.exit(2);
}

let failed = false;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(readFileSync(file));
  } catch (e) {
    console.error(`validate_gltf: ${e.message}`);
    process.exit(2);
  }
  // The exports embed their buffer: an external resource is not looked for.
  const report = await validator.validateBytes(bytes, {
    uri: file, maxIssues: 0, writeTimestamp: false });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos`);
  for (const message of issues.messages) {
    if (message.severity === 0) {
      console.log(`  error ${message.code} at ${message.pointer ?? '/'}: ${message.message}`);
      failed = true;
    }
  }
}
process.exit(failed ? 1 : 0);
