// One studio page per test file. `useStudio()` registers the hooks: before the file's tests it
// launches Debian's Chromium and opens the studio (waiting for the first plant); after them it closes
// the browser. `browser`, `page` and `problems` are ES module live bindings assigned in that hook:
// read them inside hooks and tests, never at import time. Vitest runs every test file with its own
// copy of this module (isolation is on), so files never share a page.
import { chromium, type Browser, type Page } from 'playwright-core';
import { afterAll, beforeAll } from 'vitest';
import { openStudio } from './studio-page';

export let browser: Browser;
export let page: Page;
/** The console errors, page errors, failed requests and HTTP errors the page showed. */
export let problems: string[];

/** Opens the studio before this file's tests and closes it after them; `args` go to Chromium. */
export function useStudio(args: string[] = []): void {
  beforeAll(async () => {
    browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args });
    ({ page, problems } = await openStudio(browser));
  });
  afterAll(async () => {
    await browser?.close();
  });
}
