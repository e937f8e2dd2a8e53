// Runs the Khronos glTF Validator (npm package gltf-validator) on every .gltf/.glb given
// on the command line and fails when any has an error; warnings and infos are printed.
//   node validate_gltf.mjs MODULE_DIR FILE...
// MODULE_DIR is the node_modules folder `make test` installs it into (build/node/node_modules).
import { createRequire } from "node:module";
import fs from "node:fs";
import path from "node:path";

const [moduleDir, ...files] = process.argv.slice(2);
const validator = createRequire(path.join(path.resolve(moduleDir), "noop.js"))("gltf-validator");

let failed = 0;
for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 100,
        externalResourceFunction: (uri) =>
            fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
    });
    const { numErrors, numWarnings, numInfos, messages } = report.issues;
    console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`);
    for (const m of messages)
        if (m.severity <= 1) console.log(`  ${m.severity === 0 ? "error" : "warning"} ${m.code} ${m.pointer ?? ""}: ${m.message}`);
    if (numErrors > 0) failed += 1;
}
if (failed > 0) {
    console.log(`${failed} of ${files.length} files have errors`);
    process.exit(1);
}
