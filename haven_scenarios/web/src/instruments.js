// The page a participant answers the study's instruments on, before the first trial (consent,
// then demographics, NARS, ...) and after the last (the ranking of the conditions): one at a time,
// as the per-trial questionnaires are shown (questionnaire.js). Each is sent to `haven study run`
// (web/instrument_server.py) with a POST; the server checks and stores it and says what is left.
// Not agreeing to the consent ends the page: the participant is thanked and runs no trial.
import { QuestionnaireForm } from "./questionnaire.js";
import { goOn } from "./next_page.js";

const cfg = JSON.parse(document.getElementById("config").textContent);
const state = { answered: [...cfg.answered], questionnaire: null, declined: cfg.declined, done: false };
window.havenState = state; // (the browser tests read it)

const prompt = document.getElementById("prompt");
const form = new QuestionnaireForm(document.getElementById("questionnaire"), (q, answers) => {
  fetch(cfg.answers_url, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify({ questionnaire: q.name, answers }) })
    .then(async (r) => {
      const reply = await r.json().catch(() => ({ error: `the study answered ${r.status}` }));
      if (!r.ok) return form.refusedBy(reply.error || `the study answered ${r.status}`);
      state.answered = reply.answered;
      state.declined = reply.declined;
      next();
    })
    .catch(() => form.refusedBy("Not connected to the study: please press Submit again in a moment."));
  return true;
});
window.havenForm = form;

function say(title, text) {
  form.hide();
  prompt.querySelector("h1").textContent = title;
  prompt.querySelector("p").textContent = text;
  prompt.hidden = false;
}

function next() {
  const pending = cfg.questionnaires.filter((q) => !state.answered.includes(q.name));
  if (state.declined) {
    state.questionnaire = null;
    state.done = true;
    if (goOn(cfg.next_url)) return say("Thank you", "You chose not to take part: the study ends here.");
    return say("Thank you", "You chose not to take part: the study ends here. Please tell the researcher.");
  }
  if (!pending.length) {
    state.questionnaire = null;
    state.done = true;
    if (goOn(cfg.next_url)) return say("Thank you", "Taking you on…");
    return say("Thank you", cfg.done_text);
  }
  const q = pending[0];
  state.questionnaire = q.name;
  form.show(q, cfg.questionnaires.indexOf(q) + 1, cfg.questionnaires.length);
}

next();
