import js from '@eslint/js';
import tseslint from 'typescript-eslint';

export default tseslint.config(
  {
    ignores: [
      '**/dist/**',
      '**/.bundle/**',
      '**/node_modules/**',
      'firmware/**',
      'artifacts/**',
      '**/build/**',
    ],
  },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    rules: {
      '@typescript-eslint/no-explicit-any': 'error',
      '@typescript-eslint/consistent-type-imports': 'error',
      '@typescript-eslint/no-unused-vars': [
        'error',
        { argsIgnorePattern: '^_', varsIgnorePattern: '^_' },
      ],
      'no-console': 'error',
    },
  },
  {
    files: [
      '**/*.test.ts',
      'tests/**',
      'bench/**',
      'examples/**',
      'apps/**/scripts/**',
      'scripts/**',
    ],
    rules: { 'no-console': 'off' },
  },
);
