/* The report's trace viewer (see apbot/bench/report/viewer.py for the data it reads).
   It draws a task's details when the task is opened and filters the task list. Plain
   JavaScript, no library, no network: the page must work offline and as a mail attachment.
   Every text reaches the page through textContent, never as HTML. */
(() => {
  "use strict";
  const STYLES = new Set(["mark", "ok", "bad", "muted", "rep"]);
  const source = document.getElementById("viewer-data");
  const status = document.getElementById("viewer-status");
  if (!source || !status) return;

  async function unpack(text) {
    const bytes = Uint8Array.from(atob(text.trim()), (c) => c.charCodeAt(0));
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    return JSON.parse(await new Response(stream).text());
  }

  function node(tag, text, css) {
    const element = document.createElement(tag);
    if (text !== undefined && text !== null) element.textContent = String(text);
    if (css) element.className = css;
    return element;
  }

  function fill(cell, content) {
    if (!Array.isArray(content)) {
      cell.textContent = String(content);
      return;
    }
    for (const part of content) {
      if (typeof part === "string") cell.append(part);
      else if (part[0] === "mark") cell.append(node("mark", part[1]));
      else if (STYLES.has(part[0])) cell.append(node("span", part[1], part[0]));
      else cell.append(String(part[1]));
    }
  }

  function scrolling(table) {
    const box = node("div", null, "wide");
    box.append(table);
    return box;
  }

  function table(header, rows, css) {
    const element = node("table", null, css);
    const head = element.createTHead().insertRow();
    for (const name of header) head.append(node("th", name));
    const body = element.createTBody();
    for (const [style, ...cells] of rows) {
      const row = body.insertRow();
      if (style) row.className = style;
      cells.forEach((content, i) => {
        const cell = row.insertCell();
        if (i === cells.length - 1 && cells.length < header.length) {
          cell.colSpan = header.length - cells.length + 1;
        }
        fill(cell, content);
      });
    }
    return scrolling(element);
  }

  function line(label, ...parts) {
    const paragraph = node("p");
    paragraph.append(node("b", label + ": "), ...parts);
    return paragraph;
  }

  function details(task, traces) {
    const out = [line("Instruction", task.ins)];
    const goal = task.goal.map(([name, want, got]) => ["", name, want, got === null ? "—" : got]);
    out.push(table(["variable", "goal", "final (true)"], goal, "kv"));
    if (task.gm === "read") {
      if (task.pg === null) out.push(line("Goal read from the instruction", "none"));
      else {
        const verdict = task.gx === null ? "" : task.gx ? " (the stored goal)" : " (not the stored goal)";
        out.push(line("Goal read from the instruction" + verdict, ""));
        out.push(table(["", "variable (belief)", "value"], task.pg.map(([n, v]) => ["", n, v]), "kv"));
      }
    }
    if (task.go.length) out.push(line("Read goal values the belief lacks (handed over as said)", task.go.join("; ")));
    if (task.bh) out.push(line("Belief", task.bh + (task.lf ? ` · learnt over ${task.lf} earlier task(s)` : "")));
    if (task.bd.length) out.push(line("Read belief vs the truth", task.bd.join("; ")));
    const outcome = task.ok ? "success" : "failure: " + task.why;
    out.push(
      line(
        "Outcome",
        `${outcome} · claimed success: ${task.claim ? "yes" : "no"} · category ${task.c} · ` +
          `${task.gv} goal variable${task.gv === 1 ? "" : "s"}`
      )
    );
    if (task.faults.length) out.push(line("Faults injected", task.faults.join("; ")));
    if (task.repairs.length) {
      const marked = [];
      task.repairs.forEach((text, i) => {
        if (i) marked.push("; ");
        marked.push(node("span", text, "rep"));
      });
      out.push(line("Repairs", ...marked));
    }
    const rows = traces[task.tr];
    if (!rows.length) out.push(node("p", "No trace recorded.", "muted"));
    else out.push(table(["step", "event", "action / check", "display / detail"], rows, "tr"));
    return out;
  }

  function draw(element, data) {
    if (!element.matches("details.t[data-i]") || !element.open || element.dataset.drawn) return;
    element.dataset.drawn = "1";
    element.append(...details(data.tasks[Number(element.dataset.i)], data.traces));
  }

  function filtering(data) {
    const text = document.getElementById("filter-text");
    const failures = document.getElementById("filter-failures");
    const count = document.getElementById("filter-count");
    const haystack = data.tasks.map((t) =>
      [t.m, `${t.a}/${t.t}`, t.c.replace(/_/g, " "), t.ins, t.why].join(" ").toLowerCase()
    );
    const groups = [...document.querySelectorAll("details.g")].map((group) => ({
      group,
      open: group.open,
      tasks: [...group.querySelectorAll("details.t[data-i]")],
    }));
    const sections = [...document.querySelectorAll("section.method")];
    function apply() {
      const terms = text.value.toLowerCase().split(/\s+/).filter(Boolean);
      const failuresOnly = failures.checked;
      let shown = 0;
      for (const { group, open, tasks } of groups) {
        let visible = 0;
        for (const task of tasks) {
          const i = Number(task.dataset.i);
          const keep =
            (!failuresOnly || !data.tasks[i].ok) && terms.every((t) => haystack[i].includes(t));
          task.hidden = !keep;
          visible += keep ? 1 : 0;
        }
        group.hidden = visible === 0;
        group.open = terms.length ? visible > 0 : open;
        shown += visible;
      }
      for (const section of sections) {
        const none = section.querySelector(".none");
        const any = section.querySelector("details.g:not([hidden])");
        if (none) none.hidden = Boolean(any) || !section.querySelector("details.g");
      }
      const active = terms.length > 0 || failuresOnly;
      count.textContent = active ? `${shown} of ${data.tasks.length} tasks shown` : "";
    }
    text.addEventListener("input", apply);
    failures.addEventListener("change", apply);
    document.getElementById("filter").hidden = false;
    apply();
  }

  unpack(source.textContent)
    .then((data) => {
      document.addEventListener("toggle", (event) => draw(event.target, data), true);
      for (const element of document.querySelectorAll("details.t[data-i]")) draw(element, data);
      filtering(data);
      status.hidden = true;
      document.body.dataset.viewer = "ready";
    })
    .catch((error) => {
      status.textContent =
        "The task details could not be unpacked in this browser (" +
        error +
        "); results.jsonl holds them in full.";
      document.body.dataset.viewer = "failed";
    });
})();
