// The phone page's script: asks the laptop for the question every 2 s (every 10 s while the
// page is hidden, at once when it shows again or the network comes back), shows the choices as
// buttons and sends a tap as a vote. When the lecturer changes the setup while the vote is open,
// the question is the new one and a vote already cast is dropped: the page says to vote again.
// Everything from the server is put on the page as text.
"use strict";
(function () {
  const base = document.querySelector('meta[name="poll-base"]').content;
  const stepText = document.getElementById("step");
  const questionText = document.getElementById("question");
  const choicesBox = document.getElementById("choices");
  const statusText = document.getElementById("status");
  const letter = (i) => String.fromCharCode(65 + i);

  // An anonymous id for this phone, kept across reloads (a new one where storage is refused).
  function newId() {
    const bytes = new Uint8Array(12);
    crypto.getRandomValues(bytes);
    return Array.from(bytes, (b) => b.toString(16).padStart(2, "0")).join("");
  }
  let device = null;
  try {
    device = localStorage.getItem("pollDevice");
    if (!device || !/^[A-Za-z0-9_-]{8,64}$/.test(device)) {
      device = newId();
      localStorage.setItem("pollDevice", device);
    }
  } catch (e) {
    device = newId();
  }

  let view = null;     // the last state the laptop sent
  let shownKey = "";   // the question (step and round) the buttons are for
  let message = "";    // the last vote's outcome, said once
  let offline = false;
  let timer = 0;

  function say(text) {
    if (statusText.textContent !== text) statusText.textContent = text;
  }

  function render() {
    if (!view || !view.asking) {
      stepText.textContent = "";
      questionText.textContent = offline ? "No connection to the lecture yet." :
                                           "Waiting for the next question…";
      choicesBox.replaceChildren();
      shownKey = "";
      say(offline ? "No connection: trying again." : "");
      return;
    }
    const key = view.step + "/" + view.round + "/" + view.question;
    if (key !== shownKey) {
      shownKey = key;
      message = "";
      stepText.textContent = "Step " + view.step + (view.round > 1 ? ", vote " + view.round : "");
      questionText.textContent = view.question;
      choicesBox.replaceChildren(...view.choices.map((text, i) => {
        const button = document.createElement("button");
        button.type = "button";
        button.className = "choice";
        const l = document.createElement("span");
        l.className = "letter";
        l.textContent = letter(i);
        const stop = document.createElement("span"); // "A. Stops" to a screen reader
        stop.className = "visually-hidden";
        stop.textContent = ". ";
        const t = document.createElement("span");
        t.className = "text";
        t.textContent = text;
        const m = document.createElement("span");
        m.className = "mark";
        button.append(l, stop, t, m);
        button.addEventListener("click", () => vote(i));
        return button;
      }));
    }
    Array.from(choicesBox.children).forEach((button, i) => {
      const mine = view.mine === i;
      button.setAttribute("aria-pressed", mine ? "true" : "false");
      button.querySelector(".mark").textContent = mine ? "✓ your vote" : "";
      button.disabled = !view.open;
    });
    const yours = view.mine === null ? "" : "Your vote: " + letter(view.mine) + ".";
    if (offline) say("No connection: trying again. " + yours);
    else if (!view.open) say("The vote is closed. " + (yours || "You did not vote."));
    else if (view.changed && !yours) say("The setup changed: read the question again and vote again.");
    else say(message || (yours ? yours + " Tap another letter to change it." : "Tap a letter to vote."));
  }

  function schedule() {
    clearTimeout(timer);
    timer = setTimeout(refresh, document.hidden ? 10000 : 2000);
  }

  async function refresh() {
    try {
      const r = await fetch(base + "/state?device=" + device, { cache: "no-store" });
      if (r.ok) {
        view = await r.json();
        offline = false;
      }
    } catch (e) {
      offline = true;
    }
    render();
    schedule();
  }

  async function vote(i) {
    if (!view || !view.open) return;
    try {
      const r = await fetch(base + "/vote", {
        method: "POST",
        headers: { "Content-Type": "application/json" },
        body: JSON.stringify({ device: device, choice: i }),
      });
      offline = false;
      if (r.status === 204) {
        view.mine = i;
        message = "Your vote: " + letter(i) + ". Tap another letter to change it.";
      } else if (r.status === 409) {
        message = "";
        view.open = false;
      } else if (r.status === 429) {
        message = "Too many taps: wait a moment and tap again.";
      } else {
        message = "Your vote was not taken (" + r.status + "): tap again.";
      }
    } catch (e) {
      offline = true;
      message = "";
    }
    render();
    refresh();
  }

  document.addEventListener("visibilitychange", () => { if (!document.hidden) refresh(); });
  window.addEventListener("online", refresh);
  window.addEventListener("pageshow", refresh);
  refresh();
})();
