// The TypeScript lint (`npm run lint`: eslint over web/src, tests and scripts; a gate of
// `npm test`): a small, strict set of rules that keep the house in order, the front end's side of
// crate/tests/architecture.rs.
// - Short functions and files: a function over 120 lines (blank and comment lines not counted), a
//   file over 800 lines, is a sign it holds more than one concept. One that must stay long says why
//   on the line that lets it: `// eslint-disable-next-line max-lines-per-function -- Long because …`
//   above the function, `/* eslint-disable max-lines -- Long because … */` at the top of the file.
//   A disable comment for these rules without `-- Long because` is itself an error.
// - No unused code: variables, imports, parameters (`_name` says unused on purpose), private members.
// - Type imports say so (`import type`), so that a bundler drops them.
// The parser reads TypeScript through TypeScript's JavaScript API, which the project's TypeScript 7
// (the native port) has not: tools/lint/ gives the linter TypeScript 5, beside it.
import tseslint from './tools/lint/index.js';

/** The rules whose exceptions must give a reason. */
const measured = ['max-lines', 'max-lines-per-function'];

/** `Long because`: a disable comment for a length rule must say why the code is long. */
const longBecause = {
  meta: { type: 'problem', schema: [], messages: { why: "say why it is long: '-- Long because …'" } },
  create(context) {
    return {
      Program() {
        for (const comment of context.sourceCode.getAllComments()) {
          const directive = /^\s*eslint-disable(?:-next-line|-line)?\s(.*)$/s.exec(comment.value);
          if (!directive) continue;
          const [list, reason = ''] = directive[1].split(/\s--\s/, 2);
          const rules = list.split(',').map((rule) => rule.trim());
          if (rules.some((rule) => measured.includes(rule)) && !/^Long because \S/.test(reason.trim())) {
            context.report({ loc: comment.loc, messageId: 'why' });
          }
        }
      },
    };
  },
};

export default [
  { ignores: ['node_modules/', 'dist/', 'crate/', 'test-results/', 'tools/', 'public/'] },
  {
    files: ['web/src/**/*.ts', 'tests/**/*.ts', 'scripts/**/*.ts'],
    languageOptions: { parser: tseslint.parser, ecmaVersion: 'latest', sourceType: 'module' },
    linterOptions: { reportUnusedDisableDirectives: 'error' },
    plugins: { '@typescript-eslint': tseslint.plugin, meristem: { rules: { 'long-because': longBecause } } },
    rules: {
      'max-lines-per-function': ['error', { max: 120, skipBlankLines: true, skipComments: true }],
      'max-lines': ['error', { max: 800 }],
      'meristem/long-because': 'error',
      '@typescript-eslint/no-unused-vars': [
        'error',
        { args: 'after-used', argsIgnorePattern: '^_', varsIgnorePattern: '^_', caughtErrors: 'none' },
      ],
      'no-unused-private-class-members': 'error',
      'no-unreachable': 'error',
      '@typescript-eslint/consistent-type-imports': 'error',
    },
  },
];
