// embed.html: one plant for an <iframe>, from a share link's state in the fragment
// (`embed.html#s=…`, what the studio's Share dialog gives) and the controls in the query
// (`?controls=iterations,sliders`); the growth as the link keeps it, or as the query asks
// (`?animate&loop&speed=1&t=2&from=0&to=4`, as `<meristem-plant>`'s attributes). Nothing but the plant, its controls and "Open in Meristem".
import { loadVocabulary } from '../core';
import { decodeState, hasSharedState, type SharedGrowth } from '../share';
import { EmbedPlant, growthAttributes, parseControls } from './embed-plant';
import { EMBED_CSS } from './embed-style';
import { sharedBuilds } from './shared-builds';

/** The growth the query asks for (its parameters as `<meristem-plant>`'s attributes), or undefined. */
function queryGrowth(query: URLSearchParams): SharedGrowth | undefined {
  return growthAttributes({ getAttribute: (name) => query.get(name), hasAttribute: (name) => query.has(name) });
}

async function start(): Promise<void> {
  const style = document.createElement('style');
  style.textContent = EMBED_CSS.replace(':host', '.mp-host');
  document.head.append(style);
  const host = document.getElementById('plant')!;
  const controls = parseControls(new URLSearchParams(location.search).get('controls'));
  const decoded = hasSharedState(location.hash) ? await decodeState(location.hash) : { ok: false as const, error: 'no plant in the address (embed.html#s=…, from the studio’s Share dialog)' };
  if (!decoded.ok) {
    const note = document.createElement('p');
    note.className = 'mp-failed';
    note.setAttribute('role', 'status');
    note.textContent = `This embedded plant could not be shown: ${decoded.error}.`;
    host.append(note);
    return;
  }
  if (controls.has('sliders')) await loadVocabulary(); // the sliders read the text with it
  const { text, iterations, seed } = decoded.state;
  const growth = queryGrowth(new URLSearchParams(location.search)) ?? decoded.state.growth;
  new EmbedPlant(host, { source: text, iterations, seed, controls, growth, siteRoot: new URL('./', location.href).href, builds: sharedBuilds() });
}

void start();
