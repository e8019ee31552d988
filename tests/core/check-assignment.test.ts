// An assignment file checked from the command line, as the studio's assignment panel checks it
// (docs/ASSIGNMENTS.md): `ASSIGNMENT=path/to/a1.md npx vitest run tests/core/check-assignment.test.ts`
// fails with FILE:LINE: field: problem for each problem. Without ASSIGNMENT, it checks every file
// of public/assignments/ (the examples shipped with the studio).
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { assignmentProblems } from './assignment-builder';

const EXAMPLES = fileURLToPath(new URL('../../public/assignments', import.meta.url));
const files = process.env.ASSIGNMENT ? [process.env.ASSIGNMENT] : readdirSync(EXAMPLES).filter((f) => f.endsWith('.md')).map((f) => join(EXAMPLES, f));

describe('assignment files', () => {
  it.each(files.map((file) => [relative(process.cwd(), file)]))('%s has no problem', async (file) => {
    const found = await assignmentProblems(readFileSync(file, 'utf8'));
    expect(found.map((p) => `${file}:${p.line}: ${p.field}: ${p.message}`)).toEqual([]);
  });
});
