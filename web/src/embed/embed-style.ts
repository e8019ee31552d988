// The look of an embedded plant, for the shadow root of <meristem-plant> and for embed.html alike:
// self-contained (a course page's own styles do not reach into the element), light and dark.
export const EMBED_CSS = `
:host { display: block; position: relative; min-width: 320px; min-height: 240px; height: 360px; }
.mp {
  --mp-bg: #eceef1; --mp-panel: #ffffff; --mp-text: #1f2328; --mp-muted: #5c6670; --mp-border: #d5dbe1;
  --mp-accent: #2e7d32; --mp-focus: #1f6feb;
  display: flex; flex-direction: column; box-sizing: border-box; width: 100%; height: 100%;
  border: 1px solid var(--mp-border); border-radius: 8px; overflow: hidden;
  background: var(--mp-panel); color: var(--mp-text);
  font: 14px/1.4 system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif;
}
@media (prefers-color-scheme: dark) {
  .mp { --mp-bg: #1c1f24; --mp-panel: #1b1f24; --mp-text: #e6edf3; --mp-muted: #9aa4ae; --mp-border: #30363d; --mp-accent: #3fa34d; --mp-focus: #58a6ff; }
}
.mp-view { position: relative; flex: 1 1 auto; min-height: 120px; background: var(--mp-bg); }
.mp-view canvas { position: absolute; inset: 0; display: block; width: 100%; height: 100%; touch-action: none; }
.mp-view canvas:focus-visible { outline: 3px solid var(--mp-focus); outline-offset: -3px; }
.mp-failed { margin: 0; padding: 12px; border: 1px solid #c62828; border-radius: 8px; color: #c62828; font: 14px/1.4 system-ui, sans-serif; overflow-wrap: anywhere; }
.mp-message { position: absolute; inset: auto 8px 8px 8px; z-index: 1; margin: 0; padding: 4px 8px; border-radius: 6px;
  background: var(--mp-panel); color: #c62828; font-size: 13px; }
.mp-message.mp-busy { color: var(--mp-muted); }
.mp-note { position: absolute; inset: 8px 8px auto 8px; z-index: 1; margin: 0; padding: 4px 8px; border-radius: 6px;
  background: var(--mp-panel); color: #c62828; font-size: 13px; overflow-wrap: anywhere; }
.mp-message[hidden], .mp-hidden { display: none; }
.mp-bar { display: flex; flex-wrap: wrap; align-items: center; gap: 6px; padding: 6px 8px; border-top: 1px solid var(--mp-border); }
.mp-button { min-width: 32px; padding: 3px 10px; border: 1px solid var(--mp-border); border-radius: 6px;
  background: var(--mp-panel); color: var(--mp-text); font: inherit; font-weight: 600; cursor: pointer; }
.mp-button:hover { border-color: var(--mp-accent); }
.mp-button:focus-visible, .mp-open:focus-visible, .mp-sliders input:focus-visible { outline: 2px solid var(--mp-focus); outline-offset: 1px; }
.mp-button[aria-pressed='true'] { border-color: var(--mp-accent); }
.mp-count { min-width: 3.5em; text-align: center; font-variant-numeric: tabular-nums; }
.mp-open { margin-left: auto; color: var(--mp-accent); font-weight: 600; text-decoration: none; white-space: nowrap; }
.mp-open:hover { text-decoration: underline; }
.mp-sliders { display: grid; grid-template-columns: auto minmax(60px, 1fr) auto auto; gap: 2px 8px; align-items: center;
  max-height: 40%; overflow: auto; padding: 4px 8px 8px; border-top: 1px solid var(--mp-border); font-size: 13px; }
.mp-sliders .slider-row { display: contents; }
.mp-sliders label, .mp-sliders output { font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; }
.mp-sliders input { width: 100%; margin: 0; accent-color: var(--mp-accent); }
.mp-sliders .slider-bounds { color: var(--mp-muted); font-size: 11.5px; white-space: nowrap; }
`;
