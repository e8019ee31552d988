// Scene colours for the page's light and dark schemes.
import { Color } from 'three';

/** The colours of the 3D view in one colour scheme. */
export interface ScenePalette {
  background: Color;
  /** The grid's centre lines and its other lines: low contrast, they only hint at the ground. */
  gridCenter: Color;
  grid: Color;
}

/** The palette for a light (`false`) or dark (`true`) page. Keep in sync with `--view-bg` in styles/page.css. */
export function scenePalette(dark: boolean): ScenePalette {
  return dark
    ? { background: new Color('#1c1f24'), gridCenter: new Color('#30353c'), grid: new Color('#262a30') }
    : { background: new Color('#eceef1'), gridCenter: new Color('#d9dce1'), grid: new Color('#dfe2e6') };
}
