// exgen practice: check an answer, show a hint or the worked solution without reloading the page.
// The forms work without this script (the server answers with the whole page); with it, the server
// sends the changed piece as HTML it has already escaped, and focus stays where the student is.
"use strict";
document.addEventListener("submit", async (event) => {
  const form = event.target;
  const target = form.dataset && document.getElementById(form.dataset.target || "");
  if (!target) return;  // an ordinary form: "Another one", "Practise ..."
  event.preventDefault();
  const button = form.querySelector("button");
  if (button) button.disabled = true;
  try {
    const response = await fetch(form.action, {
      method: "POST",
      body: new URLSearchParams(new FormData(form)),
      headers: { "Accept": "application/json" },
    });
    const data = await response.json();
    if (!response.ok) throw new Error(data.error || response.statusText);
    target.innerHTML = data.html;
    if (data.standing) document.getElementById("standing").textContent = data.standing;
    for (const [name, text] of Object.entries(data.costs || {})) {  // what help costs now
      for (const cost of document.querySelectorAll(".cost")) {
        if (cost.dataset.cost === name) cost.textContent = text;
      }
    }
    if (form.classList.contains("hint-form")) {
      if (button) button.disabled = !data.more;
      const hints = target.querySelectorAll(".hint");
      if (hints.length) { hints[hints.length - 1].setAttribute("tabindex", "-1"); }
      form.closest(".part").querySelector("input[name=answer]").focus();
      return;
    }
    if (form.classList.contains("solution-form")) {
      const heading = document.getElementById("solution-heading");
      if (heading) heading.focus();
      return;  // the button stays disabled: the solution is shown
    }
    if (button) button.disabled = false;
    if (data.correct) {  // on to the next part, or to "Another one" after the last
      const part = form.closest(".part");
      const next = part && part.nextElementSibling;
      const field = next ? next.querySelector("input[name=answer]") : document.getElementById("another");
      if (field) field.focus();
    }
  } catch (error) {
    if (button) button.disabled = false;
    target.textContent = "Could not reach exgen: " + error.message + ". Is `exgen serve` still running?";
  }
});
