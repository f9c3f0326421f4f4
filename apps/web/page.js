// draught's web page. The module (draught.js/.wasm, from apps/web/main.cpp) renders and
// simulates a scene of glasses; this file builds the panel from the parameter table the
// module exports, feeds it input (mouse, touch, motion sensors) and shows what it is doing.
// In a scene of several glasses one is selected (a click or tap on it, or the picker):
// input drives it and the panel edits it.
//
// URL options: ?size=WxH pins the canvas's CSS size; ?scale=S pins the render scale (else it
// adapts to ?budget=MS per frame, default 33); ?preserve keeps the drawing buffer (tests read
// pixels back); ?nomatcap keeps the full tier when the budget cannot be held at 50 % (else the
// page falls to the MatCap tier, docs/MATCAP.md, and says so).
'use strict';
(() => {
  const $ = (id) => document.getElementById(id);
  const query = new URLSearchParams(location.search);
  const canvas = $('canvas');
  const api = {};
  let M = null;
  // For tests and the console.
  const page = (window.draught = {
    ready: false,
    error: '',
    lastExport: '',
    frames: () => (M ? M._draught_frames() : 0),
    status: () => (M ? JSON.parse(api.status()) : {}),
    objects: () => {
      const o = M ? JSON.parse(api.objects()) : {};
      return Array.isArray(o.objects) ? o : { selected: 0, objects: [] };
    },
  });

  function say(text, error = false) {
    const m = $('message');
    m.textContent = text;
    m.classList.toggle('error', !!error);
  }

  const size = /^(\d+)x(\d+)$/.exec(query.get('size') || '');
  if (size) {
    document.body.classList.add('fixed-size');
    canvas.style.width = size[1] + 'px';
    canvas.style.height = size[2] + 'px';
  }

  if (typeof createDraught !== 'function') {
    say('draught.js did not load', true);
    return;
  }
  createDraught({ canvas, print: (t) => console.log(t), printErr: (t) => console.warn(t) }).then(start, (e) => {
    page.error = 'could not load the renderer: ' + e;
    say(page.error, true);
  });

  // Limits checked before text reaches the module, in messages that state them. A preset file:
  // the CLI's limit for any text input (kMaxTextFileBytes, src/core/io/files.hpp). A panel
  // value: far above any real one (a 32-point profile curve takes under 1 KiB).
  const kMaxFileBytes = 16 * 1024 * 1024;
  // An environment image: a 4k x 2k Radiance file is about 20-30 MiB; its chain of levels
  // as floats takes about 1.4 x 12 bytes per texel of the heap.
  const kMaxEnvironmentBytes = 64 * 1024 * 1024;
  const kMaxDecalBytes = 80 * 1024 * 1024;  // kMaxPngFileBytes (core/io/image.hpp)
  // A point cloud file: 128 MiB holds 4M points (the most a cloud may have) of a binary PLY
  // with radius and temperature; the bytes are copied once into the module's heap.
  const kMaxCloudBytes = 128 * 1024 * 1024;
  const kMaxValueBytes = 4096;
  const encoder = new TextEncoder();
  // (Text longer than the file limit in characters is over it in bytes too: no need to encode it.)
  const utf8Bytes = (text) => (text.length > kMaxFileBytes ? text.length : encoder.encode(text).length);
  const mib = (n) => `${(n / (1024 * 1024)).toFixed(1)} MiB`;
  const tooLargeFile = (name, bytes) => bytes > kMaxFileBytes
    ? `${name}: ${mib(bytes)}, larger than the limit of 16 MiB for a preset file; nothing was loaded` : '';
  const tooLongValue = (path, text) => {
    const n = utf8Bytes(text);
    return n > kMaxValueBytes
      ? `field '${path.slice(0, 200)}': ${n} bytes of text, longer than the limit of ${kMaxValueBytes} bytes for a value; nothing was applied`
      : '';
  };

  // Why a call into the module threw, in words for the page.
  function failure(name, e) {
    if (e instanceof RangeError)  // the browser's stack: input too deep or too large for it
      return `the input is too large or nested too deeply to handle (${e.message}); nothing was applied`;
    const what = typeof e === 'number' ? 'an unexpected C++ exception' : (e && e.message) || String(e);
    return `the renderer failed in ${name} (${what}); reload the page if this keeps happening`;
  }

  // A function of the module. String arguments go through the heap (malloc, UTF-8, free), never
  // the module's stack: ccall copies them onto its 5 MB stack, and a few megabytes of text
  // overran it and broke every later call. A call that throws anyway gives its reply in the
  // function's own form ('string': the message, 'json': {"error": message}), with the module's
  // stack put back where it was, so callers show a message and later calls work.
  function wrap(name, ret, args) {
    const f = M['_' + name];
    return (...values) => {
      const sp = M.stackSave();
      const held = [];
      try {
        const argv = values.map((v, i) => {
          if (args[i] !== 'string' && args[i] !== 'bytes') return v;
          const bytes = args[i] === 'bytes' ? v : encoder.encode(String(v));
          const at = M._malloc(bytes.length + 1);
          if (!at) throw new Error(`out of memory for ${bytes.length} bytes of text`);
          held.push(at);
          M.HEAPU8.set(bytes, at);  // HEAPU8 read after malloc: a growing heap replaces it
          M.HEAPU8[at + bytes.length] = 0;
          return at;
        });
        const r = f(...argv);
        return ret === 'string' || ret === 'json' ? M.UTF8ToString(r) : r;
      } catch (e) {
        M.stackRestore(sp);
        const msg = failure(name, e);
        console.error(msg);
        if (ret === 'json') return JSON.stringify({ error: msg });
        if (ret === 'string') return msg;
        say(msg, true);
        return ret === 'number' ? -1 : undefined;
      } finally {
        for (const at of held) M._free(at);
      }
    };
  }

  function start(module) {
    M = module;
    const fn = (name, ret, args = []) => wrap(name, ret, args);
    Object.assign(api, {
      start: fn('draught_start', 'string', ['string', 'number', 'number']),
      resize: fn('draught_resize', null, ['number', 'number', 'number']),
      quality: fn('draught_set_quality', null, ['number', 'number']),
      matcapFallback: fn('draught_set_matcap_fallback', null, ['number']),
      status: fn('draught_status', 'json'),
      presets: fn('draught_presets', 'json'),
      table: fn('draught_param_table', 'json'),
      values: fn('draught_param_values', 'json'),
      notes: fn('draught_param_notes', 'json'),
      setParam: fn('draught_set_param', 'string', ['string', 'string']),
      getParam: fn('draught_get_param', 'json', ['string']),
      objects: fn('draught_objects', 'json'),
      selectObject: fn('draught_select_object', 'string', ['number']),
      pick: fn('draught_pick', 'number', ['number', 'number', 'number', 'number']),
      selectAt: fn('draught_select_at', 'number', ['number', 'number', 'number', 'number']),
      testRow: fn('draught_test_row', 'string', ['number']),
      select: fn('draught_select', 'string', ['string', 'string']),
      load: fn('draught_load_preset', 'json', ['string', 'string']),
      loadEnvironment: fn('draught_load_environment', 'json', ['string', 'bytes', 'number']),
      loadCloud: fn('draught_load_cloud', 'json', ['string', 'bytes', 'number']),
      exportPreset: fn('draught_export_preset', 'json', ['string']),
      savePicture: fn('draught_save_picture', 'json', ['number', 'number']),
      loadDecal: fn('draught_load_decal', 'string', ['string', 'number', 'number', 'number']),
      pour: fn('draught_pour', null),
      setInput: fn('draught_set_input', 'string', ['string']),
      mouse: fn('draught_mouse', null, ['number', 'number', 'number', 'number', 'number', 'number', 'number']),
      touch: fn('draught_touch', null, ['number', 'number', 'number', 'number', 'number', 'number']),
      pointer: fn('draught_pointer', 'number', ['number', 'number', 'number', 'number', 'number']),
      droplets: fn('draught_droplets', 'json'),
      motion: fn('draught_device_motion', null, ['number', 'number', 'number', 'number', 'number', 'number', 'number']),
      screen: fn('draught_screen_orientation', null, ['number']),
      screenBegin: fn('draught_screen_begin', 'number', ['number', 'number']),
      screenCommit: fn('draught_screen_commit', null, ['number', 'number']),
    });
    page.api = api;
    const scale = parseFloat(query.get('scale') || '0') || 0;
    const err = api.start('#canvas', query.has('preserve') ? 1 : 0, scale);
    if (err) {
      page.error = err;
      say(err, true);
      return;
    }
    const budget = parseFloat(query.get('budget') || '0');
    if (budget > 0) api.quality(scale, budget);
    if (query.has('nomatcap')) api.matcapFallback(0);
    watchSize();
    watchContext();
    buildPickers();
    buildObjectPicker();
    buildPanel();
    wireButtons();
    wireScreen();
    wireInput();
    setInterval(showStatus, 250);
    page.ready = true;
  }

  // ---- size: CSS pixels and devicePixelRatio; the module picks the backing size ----
  function watchSize() {
    const send = () => {
      const r = canvas.getBoundingClientRect();
      api.resize(r.width, r.height, window.devicePixelRatio || 1);
    };
    send();
    if (window.ResizeObserver) new ResizeObserver(send).observe(canvas);
    window.addEventListener('resize', send);  // also fires when zoom changes the pixel ratio
  }

  // Frames per second from the module's own frame times, between two drawn frames at least a
  // second apart: frames slower than the 250 ms poll (or than a second) are counted right. While
  // no frame comes (a stall, a lost context) the readout falls with the wait.
  let fpsFrom = null, fps = 0, shownError = '';
  function showStatus() {
    const s = page.status();
    if (s.frames === undefined) {  // the module failed; wrap() has said why
      if (s.error && s.error !== shownError) say((shownError = page.error = s.error), true);
      return;
    }
    let shown = 0;
    if (s.frame_time >= 0) {
      if (!fpsFrom || s.frames < fpsFrom.frames) {
        fpsFrom = { frames: s.frames, time: s.frame_time };
      } else if (s.frames > fpsFrom.frames && s.frame_time - fpsFrom.time >= 1) {
        fps = (s.frames - fpsFrom.frames) / (s.frame_time - fpsFrom.time);
        fpsFrom = { frames: s.frames, time: s.frame_time };
      }
      const waiting = s.time - s.frame_time;
      shown = waiting > 0 ? Math.min(fps, 1 / waiting) : fps;
    }
    page.fps = shown;
    let q = `quality ${Math.round(s.scale * 100)} %`;
    if (s.events_cap) q += ` (${s.events_cap} events)`;
    if (!s.adaptive) q += ' (fixed)';
    // The fall to the low-cost glass (docs/MATCAP.md), said where the quality is.
    if (s.matcap_fallback) q += ' · MatCap tier: the full tier missed the frame budget at 50 % resolution';
    else if (s.tier === 'matcap') q += ' · MatCap tier';
    $('quality').textContent = `${q} · ${s.width}×${s.height} · ${shown.toFixed(shown < 10 ? 1 : 0)} fps`;
    $('input').textContent = 'input: ' + s.input;
    followModuleVideo(s.screen_file || '');
    $('selected').textContent = objects.length > 1 ? ` · ${objects[selected].name} (${selected + 1} of ${objects.length})` : '';
    if (s.error && s.error !== shownError) {
      shownError = page.error = s.error;
      say(s.error, true);
    }
  }

  // A lost WebGL context: the module pauses drawing and keeps the scene; when the browser gives
  // the context back, the module rebuilds its programs and textures and draws again.
  function watchContext() {
    canvas.addEventListener('webglcontextlost', () =>
      say('the WebGL context was lost (a GPU reset, or too many pages using WebGL); drawing resumes when the browser restores it', true));
    canvas.addEventListener('webglcontextrestored', () => {
      const s = page.status();
      if (!s.error) say('the WebGL context was restored; drawing again');
    });
  }

  // ---- presets ----
  let current = { drink: 'lager', glass: '' };
  let presets = [];
  function buildPickers() {
    presets = JSON.parse(api.presets());
    if (!Array.isArray(presets)) {
      say(presets.error || 'no presets', true);
      presets = [];
    }
    const drink = $('drink'), glass = $('glass');
    for (const [kind, label] of [['drink', 'Drinks'], ['scene', 'Scenes']]) {
      const group = document.createElement('optgroup');
      group.label = label;
      for (const p of presets.filter((p) => p.kind === kind)) group.append(option(p.name, p.name, p.description));
      if (group.children.length) drink.append(group);
    }
    glass.append(option('', 'suggested'));
    for (const p of presets.filter((p) => p.kind === 'glass')) glass.append(option(p.name, p.name, p.description));
    drink.value = current.drink;
    glass.value = current.glass;
    suggestedLabel();
    const choose = () => {
      const err = api.select(drink.value, glass.value);
      if (err) {
        say(err, true);
        drink.value = current.drink;
        glass.value = current.glass;
        return;
      }
      current = { drink: drink.value, glass: glass.value };
      suggestedLabel();
      refreshObjects();
      refreshValues();
      const p = presets.find((p) => p.name === current.drink && p.kind !== 'glass');
      say(p ? p.description : '');
    };
    drink.addEventListener('change', choose);
    glass.addEventListener('change', choose);
  }
  function suggestedLabel() {
    const p = presets.find((p) => p.name === $('drink').value && p.kind !== 'glass');
    $('glass').options[0].textContent = p && p.suggested_glass ? `suggested (${p.suggested_glass})` : 'suggested';
  }
  function option(value, text, title) {
    const o = document.createElement('option');
    o.value = value;
    o.textContent = text;
    if (title) o.title = title;
    return o;
  }

  // ---- the objects of the scene: which one input drives and the panel edits ----
  let objects = [], selected = 0;
  function buildObjectPicker() {
    $('object').addEventListener('change', () => selectObject(+$('object').value));
    $('next-object').addEventListener('click', () => selectObject((selected + 1) % Math.max(1, objects.length)));
    refreshObjects();
  }
  // The picker (shown only when there is a choice) and the panel's heading, from the module.
  function refreshObjects() {
    ({ objects, selected } = page.objects());
    const pick = $('object');
    pick.replaceChildren(...objects.map((o, i) => option(String(i), `${o.name} (objects[${i}])`)));
    pick.value = String(selected);
    $('object-row').hidden = objects.length < 2;
    const heading = $('object-heading');
    if (heading) heading.textContent = objects.length > 1 ? `the selected glass: ${objects[selected].name}` : 'the glass and its drink';
  }
  function selectObject(i) {
    const err = api.selectObject(i);
    if (err) {
      say(err, true);
      return err;
    }
    refreshObjects();
    refreshValues();
    say(`selected ${objects[selected].name}`);
    return '';
  }
  page.selectObject = selectObject;
  // A click or tap at (x, y) CSS pixels of the canvas: the glass there becomes the selected one.
  function selectAt(x, y, w, h) {
    const i = api.selectAt(x, y, w, h);
    if (i >= 0 && i !== selected) {
      refreshObjects();
      refreshValues();
      say(`selected ${objects[selected].name}`);
    }
  }
  page.pick = (x, y) => {  // for tests: the object under CSS pixel (x, y) of the canvas, or -1
    const r = canvas.getBoundingClientRect();
    return api.pick(x, y, r.width, r.height);
  };
  page.droplets = () => JSON.parse(api.droplets());  // for tests: the droplets trail, or {droplets: false}
  page.testRow = (n) => {  // for tests and the console: the selected glass n times side by side
    const err = api.testRow(n);
    if (!err) {
      refreshObjects();
      refreshValues();
    }
    return err;
  };

  // ---- the parameter panel, from the table: the selected glass's groups, then the scene's ----
  const controls = new Map();  // path -> { show(text), row, desc }
  let table = [];
  function buildPanel() {
    table = JSON.parse(api.table());
    const root = $('params');
    for (const [scope, title] of [['vessel', 'the glass and its drink'], ['scene', 'the scene']]) {
      const heading = document.createElement('h2');
      heading.className = 'scope';
      heading.textContent = title;
      if (scope === 'vessel') heading.id = 'object-heading';
      root.append(heading);
      const groups = new Map();
      for (const d of table.filter((d) => d.scope === scope)) {
        if (!groups.has(d.group)) groups.set(d.group, []);
        groups.get(d.group).push(d);
      }
      for (const [group, rows] of groups) {
        const details = document.createElement('details');
        details.dataset.group = group;
        if (group === 'liquid') details.open = true;
        const summary = document.createElement('summary');
        summary.textContent = group;
        details.append(summary);
        for (const d of rows) details.append(paramRow(d));
        root.append(details);
      }
    }
    refreshObjects();
    refreshValues();
  }
  // The path the module is given for a panel row: the selected object's own where there are
  // several glasses (a path without the prefix would set every glass).
  const pathFor = (d) => (d.scope === 'vessel' && objects.length > 1 ? `objects[${selected}].${d.path}` : d.path);

  function refreshValues() {
    const values = JSON.parse(api.values());
    for (const [path, c] of controls) {
      if (path in values) c.show(values[path]);
      c.error('');
    }
    refreshNotes();
  }
  // Beside a row whose value is not the one in effect, what is (the drink's colour: an
  // EBC of 0 beside an SRM of 3.5 says "in effect: 6.89 (from SRM)").
  function refreshNotes() {
    const notes = JSON.parse(api.notes());
    for (const [path, c] of controls) c.note(notes[path] || '');
  }

  // Values go to the module once per animation frame (sliders fire faster than that), to the
  // object selected when the value was entered.
  const pending = new Map();  // full path -> { row path, text }
  let flushQueued = false;
  function commit(path, text) {
    pending.set(pathFor(controls.get(path).desc), { path, text });
    if (!flushQueued) {
      flushQueued = true;
      requestAnimationFrame(flush);
    }
  }
  function flush() {
    flushQueued = false;
    for (const [full, { path, text }] of pending) {
      const err = tooLongValue(full, text) || api.setParam(full, text);
      controls.get(path).error(err);
      if (err) say(err, true);
      else if ($('message').classList.contains('error')) say('');
    }
    pending.clear();
    refreshNotes();
  }
  // For tests and the console: any path the module takes ("objects[1].liquid.fill" too).
  page.setParam = (path, text) => {
    const err = tooLongValue(String(path), String(text)) || api.setParam(String(path), String(text));
    if (!err) refreshValues();
    return err;
  };

  const fmt = (v) => String(Number(v.toPrecision(5)));
  const notOnThePage = { 'render.supersample': 'exported and used by the CLI; the page renders at its adaptive scale instead' };
  function paramRow(d) {
    const row = document.createElement('div');
    row.className = 'param';
    row.dataset.path = d.path;
    row.title = `${d.path}: ${d.doc}${d.unit ? ` (${d.unit})` : ''}\nexpected ${d.expected}; default ${d.default}` +
      (notOnThePage[d.path] ? `\n(${notOnThePage[d.path]})` : '');
    const label = document.createElement('label');
    label.textContent = d.name.replace(/_/g, ' ');
    const control = document.createElement('div');
    control.className = 'control';
    const err = document.createElement('div');
    err.className = 'err';
    const note = document.createElement('div');
    note.className = 'note';
    row.append(label, control, note, err);
    const input = (type, cls) => {
      const i = document.createElement('input');
      i.type = type;
      if (cls) i.className = cls;
      control.append(i);
      return i;
    };
    const id = 'p-' + d.path.replace(/\./g, '-');
    let show;
    if (d.type === 'float' || d.type === 'int') {
      const isInt = d.type === 'int';
      // Wide ranges get a logarithmic (or cubic, from 0) slider.
      const log = d.min > 0 && d.max / d.min >= 100;
      const cubic = !log && d.min === 0 && d.max >= 100;
      const toPos = (v) => {
        const u = log ? Math.log(v / d.min) / Math.log(d.max / d.min) : (v - d.min) / (d.max - d.min);
        return 1000 * (cubic ? Math.cbrt(Math.max(0, u)) : u);
      };
      const fromPos = (p) => {
        const u = p / 1000;
        const v = log ? d.min * Math.pow(d.max / d.min, u) : d.min + (d.max - d.min) * (cubic ? u * u * u : u);
        return isInt ? Math.round(v) : v;
      };
      const slider = !(isInt && d.max - d.min > 5000);
      let range;
      if (slider) {
        range = input('range');
        range.min = 0;
        range.max = 1000;
        range.step = isInt && d.max - d.min <= 1000 && !log && !cubic ? 1000 / (d.max - d.min) : 1;
      }
      const num = input('number');
      num.id = id;
      num.step = isInt ? 1 : 'any';
      num.min = d.min;
      num.max = d.max;
      if (range) {
        range.addEventListener('input', () => {
          const v = fromPos(+range.value);
          num.value = isInt ? String(v) : fmt(v);
          commit(d.path, num.value);
        });
      }
      num.addEventListener('change', () => {
        commit(d.path, num.value);
        if (range && num.value !== '') range.value = toPos(+num.value);
      });
      show = (t) => {
        num.value = t;
        if (range) range.value = toPos(+t);
      };
    } else if (d.type === 'bool') {
      const box = input('checkbox');
      box.id = id;
      box.addEventListener('change', () => commit(d.path, box.checked ? 'true' : 'false'));
      show = (t) => (box.checked = t === 'true');
    } else if (d.type === 'enum') {
      const sel = document.createElement('select');
      sel.id = id;
      for (const c of d.choices) sel.append(option(c, c));
      control.append(sel);
      sel.addEventListener('change', () => commit(d.path, sel.value));
      show = (t) => (sel.value = t);
    } else if (d.type === 'color') {
      // The picker shows the hue at unit brightness; values above 1 (radiances) keep their scale.
      const pick = input('color');
      const text = input('text');
      text.id = id;
      let k = 1;
      const hex = (c) => '#' + c.map((x) => Math.round(Math.min(1, Math.max(0, x / k)) * 255).toString(16).padStart(2, '0')).join('');
      pick.addEventListener('input', () => {
        const c = [1, 3, 5].map((i) => (parseInt(pick.value.substr(i, 2), 16) / 255) * k);
        text.value = c.map(fmt).join(',');
        commit(d.path, text.value);
      });
      text.addEventListener('change', () => commit(d.path, text.value));
      show = (t) => {
        text.value = t;
        const c = t.split(',').map(Number);
        if (c.length === 3 && c.every(Number.isFinite)) {
          k = Math.max(1, ...c);
          pick.value = hex(c);
        }
      };
    } else {  // vec3, curve: text as the CLI's --set takes it
      const text = input('text');
      text.id = id;
      text.spellcheck = false;
      text.addEventListener('change', () => commit(d.path, text.value));
      show = (t) => (text.value = t);
    }
    label.htmlFor = id;
    const unit = document.createElement('span');
    unit.className = 'unit';
    unit.textContent = d.unit;
    control.append(unit);
    controls.set(d.path, {
      desc: d,
      show,
      note: (text) => (note.textContent = text),
      error: (e) => {
        err.textContent = e;
        row.classList.toggle('bad', !!e);
      },
    });
    return row;
  }

  // ---- buttons: pour, load, export, sensors ----
  function wireButtons() {
    $('pour').addEventListener('click', () => api.pour());
    $('load').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      e.target.value = '';  // the same file can be loaded again
      if (!file) return;
      const big = tooLargeFile(file.name, file.size);  // refused before it is read
      if (big) return say(big, true);
      page.loadText(await file.text(), file.name);
    });
    page.loadText = (text, name) => {
      name = String(name).slice(0, 255);
      const big = tooLargeFile(name, utf8Bytes(text));
      if (big) {
        say(big, true);
        return big;
      }
      const r = JSON.parse(api.load(text, name));
      if (r.error) {
        say(r.error, true);  // nothing was applied
        return r.error;
      }
      refreshObjects();
      refreshValues();
      say(`loaded ${r.kind} "${r.name}" from ${name}`);
      return '';
    };
    $('environment').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      e.target.value = '';
      if (!file) return;
      page.loadEnvironment(new Uint8Array(await file.arrayBuffer()), file.name);
    });
    // An HDR environment's bytes (.hdr, or .exr where the build reads it) as the surroundings.
    page.loadEnvironment = (bytes, name) => {
      name = String(name).slice(0, 255);
      if (bytes.length > kMaxEnvironmentBytes) {
        const msg = `${name}: ${mib(bytes.length)}, larger than the limit of ${mib(kMaxEnvironmentBytes)} for an environment; nothing was loaded`;
        say(msg, true);
        return msg;
      }
      const r = JSON.parse(api.loadEnvironment(name, bytes, bytes.length));
      if (r.error) {
        say(r.error, true);  // nothing was applied
        return r.error;
      }
      refreshValues();
      say(`environment ${name}`);
      return '';
    };
    // A point cloud file (.ply, .xyz, .csv): shown on its own, fitted to the view, as a
    // scene of one cloud object (its panel rows then edit it; Export saves the scene).
    $('cloud').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      e.target.value = '';
      if (!file) return;
      if (file.size > kMaxCloudBytes) return say(`${file.name}: ${mib(file.size)}, larger than the limit of ${mib(kMaxCloudBytes)} for a point cloud; nothing was loaded`, true);
      page.loadCloud(new Uint8Array(await file.arrayBuffer()), file.name);
    });
    page.loadCloud = (bytes, name) => {
      name = String(name).slice(0, 255);
      if (bytes.length > kMaxCloudBytes) {
        const msg = `${name}: ${mib(bytes.length)}, larger than the limit of ${mib(kMaxCloudBytes)} for a point cloud; nothing was loaded`;
        say(msg, true);
        return msg;
      }
      const r = JSON.parse(api.loadCloud(name, bytes, bytes.length));
      if (r.error) {
        say(r.error, true);  // nothing was applied
        return r.error;
      }
      refreshObjects();
      refreshValues();
      say(`point cloud ${name}: ${r.points.toLocaleString('en-US')} points, ${+r.scale.toPrecision(3)} m per unit`);
      return '';
    };
    // A decal image: its bytes into the module's heap, written there into the page's file
    // system and set on the selected glass (the loader refuses a bad one; nothing changes).
    $('decal').addEventListener('change', async (e) => {
      const file = e.target.files[0];
      e.target.value = '';
      if (!file) return;
      if (file.size > kMaxDecalBytes) return say(`${file.name}: ${mib(file.size)}, larger than the limit of 80 MiB for a decal image; nothing was loaded`, true);
      page.loadDecal(new Uint8Array(await file.arrayBuffer()), file.name, +$('decal-layer').value);
    });
    page.loadDecal = (bytes, name, layer = 0) => {
      name = String(name).slice(0, 255);
      const at = M._malloc(Math.max(1, bytes.length));
      if (!at) return say(`${name}: out of memory for ${bytes.length} bytes`, true);
      let err;
      try {
        M.HEAPU8.set(bytes, at);
        err = api.loadDecal(name, at, bytes.length, layer);
      } finally {
        M._free(at);
      }
      if (err) {
        say(err, true);
        return err;
      }
      refreshValues();
      const layerName = layer === 1 ? 'decal_inner' : 'decal_outer';
      for (const d of document.querySelectorAll(`details[data-group="${layerName}"]`)) d.open = true;
      say(`${name} is the ${layer === 1 ? 'inner' : 'outer'} decal of ${objects.length > 1 ? objects[selected].name : 'the glass'}; place it with ${layerName}.angle, .height and .width`);
      return '';
    };
    // A file the browser downloads (the Export and Save picture buttons).
    const download = (name, blob) => {
      const url = URL.createObjectURL(blob);
      const a = document.createElement('a');
      a.href = url;
      a.download = name;
      document.body.append(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(url), 1000);
    };
    $('export').addEventListener('click', () => {
      const name = `${current.drink}-custom`;
      const r = JSON.parse(api.exportPreset(name));
      if (r.error) {
        say('export: ' + r.error, true);
        return;
      }
      const text = r.text;
      page.lastExport = text;
      download(name + '.json', new Blob([text], { type: 'application/json' }));
      say(`exported ${name}.json`);
    });
    // The picture as the CLI draws a still (2 x 2 samples, 4 x 4 where they disagree), at
    // the canvas's size on the screen (CSS pixels times the device's ratio, at most 2048 a
    // side): seconds on a software WebGL, so the message goes up first.
    $('save-picture').addEventListener('click', () => {
      const c = $('canvas').getBoundingClientRect(), dpr = Math.max(1, window.devicePixelRatio || 1);
      const fit = Math.min(1, 2048 / Math.max(c.width * dpr, c.height * dpr, 1));
      const w = Math.max(16, Math.round(c.width * dpr * fit)), h = Math.max(16, Math.round(c.height * dpr * fit));
      say(`drawing a ${w} x ${h} picture…`);
      setTimeout(() => {
        const r = JSON.parse(api.savePicture(w, h));
        if (r.error) {
          say('save picture: ' + r.error, true);
          return;
        }
        const png = M.HEAPU8.slice(r.bytes, r.bytes + r.size);
        const name = `${current.drink}.png`;
        download(name, new Blob([png], { type: 'image/png' }));
        say(`saved ${name} (${r.width} x ${r.height}, drawn in ${(r.ms / 1000).toFixed(1)} s)`);
      }, 30);
    });
    $('sensors').addEventListener('click', async () => {
      try {
        if (!window.DeviceMotionEvent && !window.DeviceOrientationEvent) throw new Error('this browser has no motion sensor events');
        // iOS asks the user; both requests start within this click (the gesture it needs).
        const asks = [window.DeviceMotionEvent, window.DeviceOrientationEvent]
          .filter((E) => E && typeof E.requestPermission === 'function')
          .map((E) => E.requestPermission());
        for (const answer of await Promise.all(asks)) if (answer !== 'granted') throw new Error(`permission ${answer}`);
        say(sensorsSeen ? 'motion sensors on' : 'motion sensors enabled; tilt the device (no readings yet)');
      } catch (e) {
        say('motion sensors: ' + (e.message || e), true);
      }
    });
  }

  // ---- the screen's live picture: a video file the user picks, or the camera ----
  // It plays in a <video> element; each new frame of it (requestVideoFrameCallback where
  // the browser has it, else whenever its time moves) goes into the screen's back texture:
  // the module gives the GL name (draught_screen_begin), Emscripten's GL.textures the
  // WebGLTexture, texSubImage2D the upload, draught_screen_commit shows it. A source that
  // fails (not a video the browser plays, a refused camera, frames too large) changes
  // nothing: the one playing before plays on.
  const kMaxScreenSide = 4096, kMaxScreenPixels = 4096 * 2160;  // core/io/video_source.hpp
  const live = { video: null, stream: null, name: '', uploads: 0 };
  page.screen = {
    uploads: () => live.uploads,
    source: () => live.name,
    video: () => live.video,
  };

  function uploadFrame(v) {
    const w = v.videoWidth, h = v.videoHeight;
    if (!w || !h || v.readyState < 2) return false;
    const id = api.screenBegin(w, h);
    if (!id) return false;  // no renderer now (a lost context)
    const gl = M.GL.currentContext.GLctx;
    gl.bindTexture(gl.TEXTURE_2D, M.GL.textures[id]);
    gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);  // rows top-down, as the screen reads them
    gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, false);
    gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
    try {
      gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, gl.RGBA, gl.UNSIGNED_BYTE, v);
    } finally {
      api.screenCommit(w, h);
    }
    ++live.uploads;
    return true;
  }

  // Uploads every new frame of `v` while it is the live source.
  function follow(v) {
    if (typeof v.requestVideoFrameCallback === 'function') {
      const onFrame = () => {
        if (live.video !== v) return;
        uploadFrame(v);
        v.requestVideoFrameCallback(onFrame);
      };
      v.requestVideoFrameCallback(onFrame);
      return;
    }
    let last = -1;
    const tick = () => {
      if (live.video !== v) return;
      if (v.currentTime !== last && uploadFrame(v)) last = v.currentTime;
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  // Makes `v` (playing, its first frame loaded) the live source; the screen shows what the
  // page streams (screen.source "") and comes on as a card when it was off.
  function adopt(v, stream, name, keepSource = false) {
    const w = v.videoWidth, h = v.videoHeight;
    if (w > kMaxScreenSide || h > kMaxScreenSide || w * h > kMaxScreenPixels) {
      stopTracks(stream);
      return `${name}: frames of ${w} x ${h} pixels, larger than a screen shows (at most ${kMaxScreenSide} a side and 4096 x 2160 in all)`;
    }
    const old = live.video, oldStream = live.stream;
    Object.assign(live, { video: v, stream, name, fromModule: keepSource });
    if (old) old.pause();
    stopTracks(oldStream);
    let err = keepSource ? '' : api.setParam('screen.source', '');
    const mode = JSON.parse(api.getParam('screen.mode'));
    if (!err && mode.value === 'off') err = api.setParam('screen.mode', 'card');
    refreshValues();
    uploadFrame(v);
    follow(v);
    return err;
  }
  function stopTracks(stream) {
    if (stream) for (const t of stream.getTracks()) t.stop();
  }

  // A <video> element for `setup` (it sets src or srcObject), muted and looping, resolved
  // once its first frame is there, rejected with a message when it cannot play.
  function playable(setup, name) {
    return new Promise((resolve, reject) => {
      const v = document.createElement('video');
      v.muted = true;
      v.loop = true;
      v.playsInline = true;
      v.crossOrigin = 'anonymous';
      v.addEventListener('loadeddata', () => v.play().then(() => resolve(v), (e) => reject(`${name}: cannot play (${e.message || e})`)), { once: true });
      v.addEventListener('error', () => {
        const code = v.error ? v.error.code : 0;
        const why = { 1: 'loading was aborted', 2: 'a network error', 3: 'it could not be decoded', 4: 'not a video this browser plays' }[code] || 'it could not be played';
        reject(`${name}: ${why}; the screen keeps what it showed`);
      }, { once: true });
      setup(v);
    });
  }

  async function useVideoFile(file, keepSource = false) {
    const url = URL.createObjectURL(file);
    try {
      const v = await playable((v) => (v.src = url), file.name);
      const err = adopt(v, null, file.name, keepSource);
      say(err || `the screen plays ${file.name} (${v.videoWidth} x ${v.videoHeight})`, !!err);
      return err;
    } catch (e) {
      URL.revokeObjectURL(url);
      say(String(e), true);
      return String(e);
    }
  }

  async function useCamera() {
    let stream;
    try {
      if (!navigator.mediaDevices || !navigator.mediaDevices.getUserMedia) throw new Error('this browser offers no camera (getUserMedia) here');
      stream = await navigator.mediaDevices.getUserMedia({ video: { width: { ideal: 1280 }, height: { ideal: 720 }, facingMode: 'environment' }, audio: false });
      const v = await playable((v) => (v.srcObject = stream), 'the camera');
      const err = adopt(v, stream, 'the camera');
      say(err || `the screen shows the camera (${v.videoWidth} x ${v.videoHeight}); screen.mode background puts it behind the glass`, !!err);
      return err;
    } catch (e) {
      stopTracks(stream);
      const msg = 'camera: ' + (e && e.message ? e.message : String(e)) + '; the screen keeps what it showed';
      say(msg, true);
      return msg;
    }
  }
  // A video screen.source names (a preset's shipped clip: the module decodes no video) is
  // read from the module's files and played here; when the source moves on, it stops.
  let moduleVideo = '';
  function followModuleVideo(file) {
    if (file === moduleVideo) return;
    moduleVideo = file;
    if (!file) {
      if (live.fromModule && live.video) {
        live.video.pause();
        Object.assign(live, { video: null, stream: null, name: '', fromModule: false });
      }
      return;
    }
    try {
      const bytes = M.FS.readFile(file);
      const name = file.split('/').pop();
      useVideoFile(new File([bytes], name, { type: /\.webm$/i.test(name) ? 'video/webm' : 'video/mp4' }), true);
    } catch (e) {
      say(`${file}: cannot be read (${e.message || e})`, true);
    }
  }

  page.screen.useFile = useVideoFile;
  page.screen.useCamera = useCamera;

  function wireScreen() {
    $('screen-file').addEventListener('change', (e) => {
      const file = e.target.files[0];
      e.target.value = '';
      if (file) useVideoFile(file);
    });
    $('screen-camera').addEventListener('click', () => useCamera());
  }

  // ---- input ----
  // The rig: "mouse" or "touch" for gestures, "+gyro" once the device reports motion.
  let gesture = matchMedia('(pointer: coarse)').matches && navigator.maxTouchPoints > 0 ? 'touch' : 'mouse';
  let sensorsSeen = false;
  function applyRig() {
    const name = sensorsSeen ? gesture + '+gyro' : gesture;
    const err = api.setInput(name);
    if (err) say(err, true);
  }

  function wireInput() {
    applyRig();
    const local = (e) => {
      const r = canvas.getBoundingClientRect();
      return [e.clientX - r.left, e.clientY - r.top, r.width, r.height];
    };
    // A click or tap (pressed and released without wandering further than a hand shakes)
    // selects the glass under it; a drag tilts the selected glass, whatever it starts on.
    const slop = { mouse: 4, touch: 10 };  // CSS pixels
    let tap = null;  // { x, y, moved } since the press, or null
    const tapStart = (p) => (tap = { x: p.clientX, y: p.clientY, moved: false });
    const tapMove = (p, limit) => {
      if (tap && Math.hypot(p.clientX - tap.x, p.clientY - tap.y) > limit) tap.moved = true;
    };
    const tapEnd = (p) => {
      if (tap && !tap.moved) selectAt(...local(p));
      tap = null;
    };

    // Mouse (and pen) through pointer events; touch has its own events below.
    let buttons = 0;
    let fingers = 0;
    const useGesture = (g) => {  // follows the pointer last used (hybrid laptops, tablets with mice)
      if (g !== gesture && !buttons && !fingers) {
        gesture = g;
        applyRig();
      }
    };
    canvas.addEventListener('pointerdown', (e) => {
      if (e.pointerType === 'touch') return;
      useGesture('mouse');
      canvas.setPointerCapture(e.pointerId);
      buttons |= 1 << e.button;
      if (e.button === 0) tapStart(e);
      api.mouse(0, e.button, ...local(e), e.shiftKey ? 1 : 0);
    });
    // In a scene with droplets, the mouse moving over the picture moves their pointer; a drag
    // tilts the selected glass as elsewhere (and moves the pointer where that is no glass).
    const droplets = () => objects.some((o) => o.kind === 'droplets');
    canvas.addEventListener('pointermove', (e) => {
      if (e.pointerType === 'touch') return;
      if (droplets()) api.pointer(...local(e), buttons ? 1 : 0);
      if (!buttons) return;
      tapMove(e, slop.mouse);
      api.mouse(1, 0, ...local(e), 0);
    });
    const up = (e) => {
      if (e.pointerType === 'touch' || !(buttons & (1 << e.button))) return;
      buttons &= ~(1 << e.button);
      api.mouse(2, e.button, ...local(e), 0);
      if (e.button === 0) tapEnd(e);
    };
    canvas.addEventListener('pointerup', up);
    canvas.addEventListener('pointercancel', (e) => {
      if (e.pointerType === 'touch') return;
      for (const b of [0, 2]) if (buttons & (1 << b)) api.mouse(2, b, ...local(e), 0);
      buttons = 0;
      tap = null;
    });
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());

    // In a scene with droplets a finger moves their pointer (the first finger down) instead of
    // the glass (the mouse and the motion sensors still move it there); a tap still selects.
    const touch = (kind) => (e) => {
      e.preventDefault();  // over the canvas only: no scrolling or zooming the page under a finger
      if (kind === 0) useGesture('touch');
      fingers = e.touches.length;
      if (kind === 3) {
        tap = null;
        api.touch(3, 0, 0, 0, 1, 1);
        return;
      }
      const pointing = droplets();
      if (pointing && kind !== 2) api.pointer(...local(e.touches[0]), 0);
      // (A finger lifted always reaches the driver: one put down before the scene changed.)
      if (!pointing || kind === 2) for (const t of e.changedTouches) api.touch(kind, t.identifier, ...local(t));
      // A tap is one finger, down and up in place; a second finger makes it a gesture.
      if (kind === 0) e.touches.length === 1 ? tapStart(e.changedTouches[0]) : (tap = null);
      else if (kind === 1) for (const t of e.changedTouches) tapMove(t, slop.touch);
      else if (e.touches.length === 0) tapEnd(e.changedTouches[0]);
    };
    const opts = { passive: false };
    canvas.addEventListener('touchstart', touch(0), opts);
    canvas.addEventListener('touchmove', touch(1), opts);
    canvas.addEventListener('touchend', touch(2), opts);
    canvas.addEventListener('touchcancel', touch(3), opts);

    // Motion sensors. devicemotion carries what the driver wants (gyro, accel with gravity);
    // where only deviceorientation arrives, both are derived from the angles.
    const D2R = Math.PI / 180;
    let lastMotion = -1e9;
    const sensorsOn = () => {
      if (!sensorsSeen) {
        sensorsSeen = true;
        applyRig();
      }
    };
    window.addEventListener('devicemotion', (e) => {
      const a = e.accelerationIncludingGravity, r = e.rotationRate;
      if (!a || a.x == null || a.y == null || a.z == null) return;
      lastMotion = e.timeStamp;
      sensorsOn();
      const rate = (v) => (v == null ? 0 : v * D2R);
      api.motion(e.timeStamp / 1000, rate(r && r.beta), rate(r && r.gamma), rate(r && r.alpha), a.x, a.y, a.z);
    });
    let prev = null;
    window.addEventListener('deviceorientation', (e) => {
      if (e.beta == null || e.gamma == null) return;
      if (e.timeStamp - lastMotion < 500) return;  // devicemotion is doing it
      sensorsOn();
      const R = rotation(e.alpha || 0, e.beta, e.gamma);
      const t = e.timeStamp / 1000;
      let w = [0, 0, 0];
      if (prev && t > prev.t && t - prev.t < 0.5) {
        // Body rates from R_prev^T R (the skew part over dt).
        const d = mul(transpose(prev.R), R), dt = t - prev.t;
        w = [(d[7] - d[5]) / (2 * dt), (d[2] - d[6]) / (2 * dt), (d[3] - d[1]) / (2 * dt)];
      }
      prev = { R, t };
      // Gravity's reaction in the device frame: R^T (0, 0, g).
      const g = 9.81, b = e.beta * D2R, c = e.gamma * D2R;
      api.motion(t, w[0], w[1], w[2], -g * Math.sin(c) * Math.cos(b), g * Math.sin(b), g * Math.cos(b) * Math.cos(c));
    });
    const orientation = () => {
      const a = screen.orientation ? screen.orientation.angle : window.orientation || 0;
      api.screen(a | 0);
    };
    orientation();
    if (screen.orientation) screen.orientation.addEventListener('change', orientation);
    window.addEventListener('orientationchange', orientation);
  }

  // Row-major 3x3 matrices. W3C device orientation: R = Rz(alpha) Rx(beta) Ry(gamma).
  function rotation(alpha, beta, gamma) {
    const [a, b, c] = [alpha, beta, gamma].map((x) => (x * Math.PI) / 180);
    const rz = [Math.cos(a), -Math.sin(a), 0, Math.sin(a), Math.cos(a), 0, 0, 0, 1];
    const rx = [1, 0, 0, 0, Math.cos(b), -Math.sin(b), 0, Math.sin(b), Math.cos(b)];
    const ry = [Math.cos(c), 0, Math.sin(c), 0, 1, 0, -Math.sin(c), 0, Math.cos(c)];
    return mul(mul(rz, rx), ry);
  }
  function mul(p, q) {
    const r = new Array(9).fill(0);
    for (let i = 0; i < 3; ++i)
      for (let j = 0; j < 3; ++j) for (let k = 0; k < 3; ++k) r[3 * i + j] += p[3 * i + k] * q[3 * k + j];
    return r;
  }
  function transpose(p) {
    return [p[0], p[3], p[6], p[1], p[4], p[7], p[2], p[5], p[8]];
  }
})();
