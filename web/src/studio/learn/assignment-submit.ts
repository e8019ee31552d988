// The assignment panel's links: "Submit…" (the student's grammar, their name and the assignment's
// identity packed into one link, to paste into the learning platform) and "Link for students" (the
// lecturer's: the address that opens this assignment). Each link is shown in a read-only field with
// Copy, so that it can be selected by hand where the clipboard is refused.
import type { Assignment } from './assignment-file.ts';
import { assignmentLink, MAX_NAME, submissionLink, type AssignmentSource, type Submission } from './assignment-links.ts';

/** The assignment the links are of. */
export interface LinkedAssignment {
  assignment: Assignment;
  source: AssignmentSource;
  text: string;
  fingerprint: string;
}

/** Where the student's name is remembered between assignments (this browser only). */
const NAME_KEY = 'meristem.assignment.name';

function rememberedName(): string {
  try {
    return localStorage.getItem(NAME_KEY) ?? '';
  } catch {
    return '';
  }
}

function rememberName(name: string): void {
  try {
    localStorage.setItem(NAME_KEY, name);
  } catch {
    // storage off: the name is typed again next time
  }
}

function labelled(text: string, control: HTMLElement): HTMLLabelElement {
  const label = document.createElement('label');
  label.className = 'assignment-field';
  label.append(text, control);
  return label;
}

function plainButton(text: string, testid: string, onClick: () => void, className = ''): HTMLButtonElement {
  const node = document.createElement('button');
  node.type = 'button';
  node.textContent = text;
  node.className = className;
  node.dataset.testid = testid;
  node.addEventListener('click', onClick);
  return node;
}

/** A read-only field holding a link, with Copy and a status line. */
function linkField(testid: string): { box: HTMLElement; show(link: string): void; say(text: string): void } {
  const box = document.createElement('div');
  box.className = 'assignment-link';
  box.hidden = true;
  const field = document.createElement('textarea');
  field.readOnly = true;
  field.rows = 3;
  field.dataset.testid = testid;
  field.setAttribute('aria-label', 'The link');
  const status = document.createElement('p');
  status.className = 'lesson-meta';
  status.setAttribute('role', 'status');
  const copy = plainButton('Copy', `${testid}-copy`, () => {
    field.select();
    navigator.clipboard.writeText(field.value).then(
      () => (status.textContent = 'The link is on the clipboard.'),
      () => (status.textContent = 'Select the link and copy it (Ctrl+C).'),
    );
  });
  box.append(field, copy, status);
  return {
    box,
    show(link) {
      field.value = link;
      status.textContent = '';
      box.hidden = false;
    },
    say(text) {
      status.textContent = text;
      box.hidden = false;
    },
  };
}

/** The panel's Submit… and "Link for students" controls. */
export class SubmitControls {
  constructor(
    private readonly linked: LinkedAssignment,
    /** The grammar in the editor now. */
    private readonly grammar: () => string,
  ) {}

  /** The controls (without Submit… when a submission is shown: the lecturer's page has nothing to submit). */
  element(reviewing: boolean): HTMLElement {
    const section = document.createElement('section');
    section.className = 'assignment-actions';
    if (!reviewing) section.append(this.submitForm());
    const students = linkField('assignment-link');
    const share = plainButton('Link for students', 'assignment-share', () => {
      void assignmentLink(location, this.linked.source, this.linked.text).then(
        (link) => students.show(link),
        (error: unknown) => students.say(`Could not make the link: ${String(error)}`),
      );
    }, 'quiet');
    section.append(share, students.box);
    return section;
  }

  /** Submit…: a name, then the link of the grammar in the editor. */
  private submitForm(): HTMLElement {
    const form = document.createElement('details');
    form.className = 'assignment-submit';
    const summary = document.createElement('summary');
    summary.textContent = 'Submit…';
    summary.dataset.testid = 'submit-open';
    const name = document.createElement('input');
    name.type = 'text';
    name.autocomplete = 'name';
    name.maxLength = MAX_NAME;
    name.value = rememberedName();
    name.dataset.testid = 'submit-name';
    const field = linkField('submit-link');
    const make = plainButton('Make the submission link', 'submit-make', () => {
      rememberName(name.value.trim());
      void this.makeLink(name.value.trim()).then((made) => (made.ok ? field.show(made.link) : field.say(`No link: ${made.error}.`)));
    }, 'primary');
    const note = document.createElement('p');
    note.className = 'lesson-meta';
    note.textContent = 'The link holds your grammar as it is in the editor now, your name and which assignment it answers. Paste it where your course collects work; whoever opens it sees your grammar and the checks, computed again.';
    form.append(summary, labelled('Your name (optional) ', name), make, note, field.box);
    return form;
  }

  private makeLink(name: string): Promise<{ ok: true; link: string } | { ok: false; error: string }> {
    const { assignment, source, text, fingerprint } = this.linked;
    const submission: Submission = { fingerprint, title: assignment.title, grammar: this.grammar(), name };
    if (source.kind === 'url') submission.url = source.url;
    else submission.text = text;
    return submissionLink(location, submission);
  }
}
