import { describe, expect, it } from 'vitest';
import { SHORTCUTS, shortcutFor } from './shortcuts';

const key = (code: string, mods: Partial<KeyboardEvent> = {}) => ({ code, altKey: true, ctrlKey: false, metaKey: false, shiftKey: false, ...mods });

describe('shortcuts', () => {
  it('maps Alt+key to its action and nothing else', () => {
    expect(shortcutFor(key('KeyP'))?.action).toBe('playPause');
    expect(shortcutFor(key('Period'))?.action).toBe('stepForward');
    expect(shortcutFor(key('KeyP', { altKey: false }))).toBeUndefined();
    expect(shortcutFor(key('KeyP', { ctrlKey: true }))).toBeUndefined();
    expect(shortcutFor(key('KeyQ'))).toBeUndefined();
  });

  it('opens the help with F1 alone', () => {
    expect(shortcutFor(key('F1', { altKey: false }))?.action).toBe('help');
    expect(shortcutFor(key('F1'))).toBeUndefined();
    expect(shortcutFor(key('F1', { altKey: false, ctrlKey: true }))).toBeUndefined();
  });

  it('has one key per action and keeps off keys browsers use with Alt', () => {
    expect(new Set(SHORTCUTS.map((s) => s.code)).size).toBe(SHORTCUTS.length);
    expect(new Set(SHORTCUTS.map((s) => s.action)).size).toBe(SHORTCUTS.length);
    for (const s of SHORTCUTS) expect(['KeyF', 'KeyE', 'KeyD', 'KeyV', 'KeyS', 'KeyB', 'KeyT', 'KeyH', 'ArrowLeft', 'ArrowRight']).not.toContain(s.code);
    for (const s of SHORTCUTS) expect(s.code).not.toMatch(/^Digit/);
  });
});
