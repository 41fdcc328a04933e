// The questionnaires after the trial, one at a time over the participant's view. Every item is a
// row of radio buttons between its two anchors: NASA-TLX the paper form's 21 marks (0..100 in
// fives), Godspeed a 5-point semantic differential (the row is its own two labels), a study's
// Likert items 1..N; an item with options (demographics, consent) a list of its options, a text item
// a line to type in (optional), a ranking (NARS-style "distinct") each rank once. The instrument's
// citation shows under its title. Nothing is preselected, and Submit is refused, saying how many items are
// missing and marking them, until every item has an answer. Keyboard: Tab moves from item to item,
// the arrow keys choose within one (Space picks the first), Enter submits.

const MISSING = "Please answer every item:";
const CONFIRM_MS = 15000; // the web node's questionnaire_answered event comes back within a second

export class QuestionnaireForm {
  // root: the overlay element; send(questionnaire, answers) -> true once the answers are on their way
  constructor(root, send) {
    this.root = root;
    this.send = send;
    this.shown = null; // the questionnaire's name
    this.refused = 0; // submits refused for missing answers (the tests read it)
  }

  show(q, position, count) {
    this.root.hidden = false;
    if (this.shown === q.name) return;
    this.shown = q.name;
    this.q = q;
    this.root.replaceChildren(this.build(q, position, count));
    this.root.scrollTop = 0;
    this.root.querySelector("input").focus({ preventScroll: true });
  }

  hide() {
    this.root.hidden = true;
    this.shown = null;
  }

  build(q, position, count) {
    const form = el("form", { className: "questionnaire", noValidate: true });
    form.append(
      el("p", { className: "progress", textContent: count > 1 ? `Questionnaire ${position} of ${count}` : "Questionnaire" }),
      el("h1", { textContent: q.title }),
    );
    if (q.source) form.append(el("p", { className: "source", textContent: `Source: ${q.source}` }));
    form.append(el("p", { className: "instructions", textContent: q.instructions }));
    const values = [];
    for (let v = q.minimum; v <= q.maximum; v += q.step) values.push(v);
    let prompt = "";
    for (const item of q.items) {
      if (item.prompt && item.prompt !== prompt) form.append(el("p", { className: "instructions prompt", textContent: item.prompt }));
      prompt = item.prompt || prompt;
      form.append(item.kind === "choice" ? this.choice(q, item) : item.kind === "text" ? this.text(q, item) : this.row(q, item, values));
    }
    this.message = el("p", { className: "missing" }, { role: "alert" });
    this.button = el("button", { type: "submit", textContent: position < count ? "Submit and go on" : "Submit" });
    form.append(this.message, this.button);
    form.addEventListener("submit", (e) => {
      e.preventDefault();
      this.submit(form);
    });
    form.addEventListener("change", (e) => {
      e.target.closest("fieldset").classList.remove("unanswered");
      if (this.message.textContent.startsWith(MISSING)) this.sayMissing(form.querySelectorAll("fieldset.unanswered").length);
    });
    return form;
  }

  sayMissing(count) {  // the refusal's count follows the answers given since; gone once none is missing
    this.message.textContent = count ? `${MISSING} ${count} ${count === 1 ? "is" : "are"} not answered yet (marked in red).` : "";
  }

  row(q, item, values) {
    const set = el("fieldset", { className: `item${q.differential ? " differential" : ""}` });
    set.dataset.item = item.id;
    set.append(el("legend", { textContent: item.text, className: q.differential ? "sr-only" : "" }));
    const marks = el("div", { className: `marks${values.length > 11 ? " fine" : ""}` });
    for (const v of values) {
      const label = el("label");
      const anchor = v === q.minimum ? `: ${item.low}` : v === q.maximum ? `: ${item.high}` : "";
      label.append(el("input", { type: "radio", name: `${q.name}.${item.id}`, value: String(v) }, { "aria-label": `${v}${anchor}` }));
      if (values.length <= 11) label.append(el("span", { textContent: String(v) }));
      marks.append(label);
    }
    const scale = el("div", { className: "scale" });
    scale.append(el("span", { className: "anchor low", textContent: item.low }), marks, el("span", { className: "anchor high", textContent: item.high }));
    set.append(scale);
    return set;
  }

  choice(q, item) {  // one of the item's options, each with its words: the answer is its number (1..n)
    const set = el("fieldset", { className: "item choice" });
    set.dataset.item = item.id;
    set.append(el("legend", { textContent: item.text }));
    const list = el("div", { className: "options" });
    item.options.forEach((words, k) => {
      const label = el("label");
      label.append(el("input", { type: "radio", name: `${q.name}.${item.id}`, value: String(k + 1) }), el("span", { textContent: words }));
      list.append(label);
    });
    set.append(list);
    return set;
  }

  text(q, item) {  // optional: never marked missing
    const set = el("fieldset", { className: "item text" });
    set.dataset.item = item.id;
    set.dataset.optional = "1";
    const label = el("label", { textContent: item.text });
    label.append(el("input", { type: "text", name: `${q.name}.${item.id}`, maxLength: 100 }));
    set.append(label);
    return set;
  }

  submit(form) {
    const answers = {};
    const missing = [];
    for (const set of form.querySelectorAll("fieldset")) {
      if (set.dataset.optional) {
        answers[set.dataset.item] = set.querySelector("input").value.trim();
        continue;
      }
      const chosen = set.querySelector("input:checked");
      set.classList.toggle("unanswered", !chosen);
      if (chosen) answers[set.dataset.item] = Number(chosen.value);
      else missing.push(set);
    }
    if (!missing.length && this.q.distinct && new Set(Object.values(answers)).size !== Object.keys(answers).length) {
      this.refused++;
      this.message.textContent = `Please use each number from ${this.q.minimum} to ${this.q.maximum} once.`;
      return;
    }
    if (missing.length) {
      this.refused++;
      this.sayMissing(missing.length);
      missing[0].scrollIntoView({ block: "center" });
      missing[0].querySelector("input").focus({ preventScroll: true });
      return;
    }
    if (!this.send(this.q, answers)) {
      this.message.textContent = "Not connected to the study: please try again in a moment.";
      return;
    }
    this.message.textContent = "";
    this.button.disabled = true;
    this.sentLabel = this.button.textContent;
    this.button.textContent = "Sending…";
    const sent = this.q.name;
    setTimeout(() => {  // not confirmed (the connection dropped on the way): let them send it again
      if (this.shown !== sent) return;
      this.button.disabled = false;
      this.button.textContent = "Submit";
      this.message.textContent = "The study has not confirmed your answers yet: please press Submit again.";
    }, CONFIRM_MS);
  }

  refusedBy(text) {  // the study refused the answers it was sent (its one line): they can change and send them again
    this.button.disabled = false;
    this.button.textContent = this.sentLabel || "Submit";
    this.message.textContent = text;
  }
}

function el(tag, props = {}, attributes = {}) {
  const e = Object.assign(document.createElement(tag), props);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  return e;
}
