// The example gallery's files: the texts of public/examples, fetched once per visit (their
// manifest: ./manifest-fetch.ts, with the dialog that shows them, ./gallery-dialog.ts, loaded
// when it is first opened).

const texts = new Map<string, Promise<string>>();

/** The text of an example (fetched once per visit). */
export function fetchExample(file: string): Promise<string> {
  let text = texts.get(file);
  if (!text) {
    text = fetch(`examples/${encodeURIComponent(file)}`).then((response) => {
      if (!response.ok) throw new Error(`examples/${file}: HTTP ${response.status}`);
      return response.text();
    });
    text.catch(() => texts.delete(file));
    texts.set(file, text);
  }
  return text;
}
