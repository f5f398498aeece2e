// tangle results report: 3D replay (three.js), plots (SVG), clash table, model summary, run log.
// The data come from the <script id="tangle-data"> element (HtmlReport.cpp writes them); units are SI
// except positions in the frames (mm) and tensions / moments (kN, kN m).
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("tangle-data").textContent);
  var frames = data.frames && data.frames.length ? data.frames : (data.statics ? [data.statics] : []);
  var isDynamic = !!(data.frames && data.frames.length);
  var staticsFailed = /statics did not converge/.test(data.status || "");
  var status = { ready: false, errors: window.TANGLE_ERRORS };
  var lineColours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf",
                     "#bcbd22", "#7f7f7f"];
  function lineColour(i) { return lineColours[i % lineColours.length]; }
  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    if (attrs) for (var k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  function fmt(v, digits) {
    if (v === null || v === undefined || !isFinite(v)) return "-";
    var a = Math.abs(v);
    if (a !== 0 && (a >= 1e6 || a < 1e-3)) return v.toExponential(Math.max(1, (digits || 4) - 1));
    return Number(v.toPrecision(digits || 4)).toString();
  }
  function deg(rad) { return rad * 180 / Math.PI; }

  // ---------------------------------------------------------------- header, model, log
  document.getElementById("title").textContent =
      (data.kind === "view" ? "tangle model view: " : "tangle report: ") + (data.title || data.model);
  document.getElementById("meta").textContent = "model " + data.model + " \u00b7 tangle " + data.version +
      " \u00b7 " + (data.status || "");
  document.getElementById("log-text").textContent = TANGLE_LOG || "(no run log)";

  (function modelSection() {
    var body = document.getElementById("model-body");
    body.appendChild(el("pre", null, data.summary));
    var t = el("table");
    t.innerHTML = "<thead><tr><th class=text>line</th><th>length (m)</th><th class=text>section type</th>" +
        "<th>section length (m)</th><th>elements</th><th>contact diameter (m)</th></tr></thead>";
    var tb = el("tbody");
    data.lines.forEach(function (line) {
      var dmax = Math.max.apply(null, line.diam);
      line.sections.forEach(function (s, k) {
        var tr = el("tr");
        [k === 0 ? line.name : "", k === 0 ? fmt(line.length, 6) : "", s.type, fmt(s.length, 6), s.elements,
         k === 0 ? fmt(dmax, 4) : ""].forEach(function (v, c) {
          tr.appendChild(el("td", c === 0 || c === 2 ? { "class": "text" } : null, String(v)));
        });
        tb.appendChild(tr);
      });
    });
    t.appendChild(tb);
    body.appendChild(t);
    if (data.vessels.length) {
      var p = el("p", null, "Vessels are drawn as boxes, or as their hulls' contact shapes: " + data.vessels.map(function (v) {
        if (v.hull && v.hull.length) return v.name + ": its hull, " + v.hull.length + " shape(s)";
        return v.name + " " + fmt(v.length, 3) + " x " + fmt(v.breadth, 3) + " m, draft " + fmt(v.draft, 3) +
            " m (" + (v.sized ? "from its current-force areas" : "no current-force areas given: nominal size") + ")";
      }).join("; ") + ".");
      body.appendChild(p);
    }
  })();

  // ---------------------------------------------------------------- quantities
  var quantities = [];
  if (data.kind !== "view") {
    quantities.push({ key: "T", label: "effective tension", unit: "kN" });
    quantities.push({ key: "M", label: "bending moment", unit: "kN m" });
    quantities.push({ key: "C", label: "curvature", unit: "1/m" });
  }
  if (frames.length && frames[0].lines.some(function (l) { return l.c; }))
    quantities.push({ key: "c", label: "clearance", unit: "m", reversed: true, clearance: true });
  if (data.kind === "view") quantities.unshift({ key: "line", label: "line", unit: "" });
  else quantities.push({ key: "line", label: "line", unit: "" });
  quantities.forEach(function (q) {
    if (q.key === "line") return;
    var lo = Infinity, hi = -Infinity;
    frames.forEach(function (f) {
      f.lines.forEach(function (l) {
        var v = l[q.key];
        if (!v) return;
        for (var i = 0; i < v.length; ++i) if (v[i] !== null) { if (v[i] < lo) lo = v[i]; if (v[i] > hi) hi = v[i]; }
      });
    });
    if (q.clearance && isFinite(lo)) {
      // Small clearances matter: the scale starts at 0 (or the deepest overlap) and ends at 10 m or
      // three times the smallest clearance, larger ones in the end colour.
      var cap = Math.max(10, 3 * Math.max(lo, 0));
      lo = Math.min(lo, 0);
      if (hi > cap) { hi = cap; q.capped = true; }
    }
    if (!isFinite(lo)) { lo = 0; hi = 1; }
    if (hi - lo < 1e-12 * Math.max(1, Math.abs(hi))) { hi = lo + Math.max(1e-9, Math.abs(lo) * 1e-3); }
    q.min = lo; q.max = hi;
  });
  // Blue - cyan - green - yellow - red.
  var stops = [[0.15, 0.25, 0.85], [0.1, 0.75, 0.9], [0.2, 0.8, 0.3], [0.95, 0.85, 0.15], [0.85, 0.1, 0.1]];
  function colourMap(u, out) {
    u = Math.min(1, Math.max(0, u)) * (stops.length - 1);
    var i = Math.min(stops.length - 2, Math.floor(u)), w = u - i;
    for (var k = 0; k < 3; ++k) out[k] = stops[i][k] * (1 - w) + stops[i + 1][k] * w;
    return out;
  }

  // ---------------------------------------------------------------- 3D scene
  var container = document.getElementById("scene");
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xdfe8f0);
  container.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  var camera = new THREE.PerspectiveCamera(40, 1, 0.1, 1e6);
  camera.up.set(0, 0, 1);
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  var sun = new THREE.DirectionalLight(0xffffff, 0.6);
  sun.position.set(0.4, -0.6, 1);
  scene.add(sun);
  var sun2 = new THREE.DirectionalLight(0xffffff, 0.25);
  sun2.position.set(-0.5, 0.7, -0.3);
  scene.add(sun2);

  // Extent of the scene: every node of every frame and the vessels.
  var box = new THREE.Box3();
  frames.forEach(function (f) {
    f.lines.forEach(function (l) {
      for (var i = 0; i < l.p.length; i += 3) box.expandByPoint(new THREE.Vector3(l.p[i] / 1000, l.p[i + 1] / 1000, l.p[i + 2] / 1000));
    });
    f.v.forEach(function (v) { box.expandByPoint(new THREE.Vector3(v[0], v[1], v[2])); });
  });
  if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  box.expandByPoint(new THREE.Vector3(box.min.x, box.min.y, -data.depth));
  box.expandByPoint(new THREE.Vector3(box.max.x, box.max.y, 0));
  var size = box.getSize(new THREE.Vector3());
  var sceneSize = Math.max(size.x, size.y, size.z, 1);
  var centre = box.getCenter(new THREE.Vector3());

  // Seabed and sea surface, a margin around the lines.
  var margin = 0.15 * sceneSize;
  var planeW = Math.max(size.x, size.y) + 2 * margin, planeH = planeW;
  if (data.seabed) {
    // A sloping or gridded seabed: the sampled heights, interpolated bilinearly (held beyond the samples).
    var sb = data.seabed;
    var heightAt = function(x, y) {
      var fx = Math.min(Math.max((x - sb.x0) / sb.step, 0), sb.n - 1),
          fy = Math.min(Math.max((y - sb.y0) / sb.step, 0), sb.n - 1);
      var i = Math.min(Math.floor(fx), sb.n - 2), j = Math.min(Math.floor(fy), sb.n - 2);
      var u = fx - i, v = fy - j, z = sb.z;
      return (1 - u) * (1 - v) * z[j * sb.n + i] + u * (1 - v) * z[j * sb.n + i + 1] +
          (1 - u) * v * z[(j + 1) * sb.n + i] + u * v * z[(j + 1) * sb.n + i + 1];
    };
    var geometry = new THREE.PlaneBufferGeometry(planeW, planeH, 60, 60);
    var pos = geometry.attributes.position;
    for (var k = 0; k < pos.count; k++) pos.setZ(k, heightAt(centre.x + pos.getX(k), centre.y + pos.getY(k)));
    geometry.computeVertexNormals();
    var bed =
        new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({color: 0xc8b58a, side: THREE.DoubleSide}));
    bed.position.set(centre.x, centre.y, 0);
    scene.add(bed);
    var wire = new THREE.LineSegments(
        new THREE.WireframeGeometry(geometry),
        new THREE.LineBasicMaterial({color: 0x9c8a60, transparent: true, opacity: 0.35}));
    wire.position.copy(bed.position);
    scene.add(wire);
  } else {
    var seabed = new THREE.Mesh(
        new THREE.PlaneBufferGeometry(planeW, planeH),
        new THREE.MeshLambertMaterial({color: 0xc8b58a, side: THREE.DoubleSide}));
    seabed.position.set(centre.x, centre.y, -data.depth);
    scene.add(seabed);
    var grid = new THREE.GridHelper(planeW, 20, 0x9c8a60, 0xb0a070);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(centre.x, centre.y, -data.depth + 0.01);
    scene.add(grid);
  }
  var sea = new THREE.Mesh(new THREE.PlaneBufferGeometry(planeW, planeH),
      new THREE.MeshLambertMaterial({ color: 0x3a7ec8, transparent: true, opacity: 0.22, side: THREE.DoubleSide,
                                      depthWrite: false }));
  sea.position.set(centre.x, centre.y, 0);
  scene.add(sea);

  // Current, wave and wind directions: arrows on the sea surface (azimuth from +x, direction of travel).
  var arrowLength = 0.18 * sceneSize;
  var envNotes = [];
  function envArrow(azimuth, colour, z, text) {
    var dir = new THREE.Vector3(Math.cos(azimuth), Math.sin(azimuth), 0);
    var origin = new THREE.Vector3(box.min.x - 0.5 * margin, box.min.y - 0.5 * margin, z);
    scene.add(new THREE.ArrowHelper(dir, origin, arrowLength, colour, 0.25 * arrowLength, 0.1 * arrowLength));
    envNotes.push("<span style='color:#" + new THREE.Color(colour).getHexString() + "'>\u2192</span> " + text);
  }
  if (data.seabed) envNotes.push('seabed: ' + data.seabed.describe);
  if (data.current.length) {
    // The current profile: one arrow per level given, at its depth, length by speed.
    var top = data.current.reduce(function (a, b) { return a.z > b.z ? a : b; });
    var vmax = Math.max.apply(null, data.current.map(function (c) { return c.speed; })) || 1;
    data.current.forEach(function (c) {
      if (c === top || !(c.speed > 0)) return;
      var dir = new THREE.Vector3(Math.cos(c.azimuth), Math.sin(c.azimuth), 0);
      var len = arrowLength * c.speed / vmax;
      scene.add(new THREE.ArrowHelper(dir, new THREE.Vector3(box.min.x - 0.5 * margin, box.min.y - 0.5 * margin,
                                      Math.max(c.z, -data.depth)), len, 0x4080e0, 0.25 * len, 0.1 * len));
    });
    envArrow(top.azimuth, 0x0050c0, Math.min(top.z, -0.02 * sceneSize), "current " + fmt(top.speed, 3) +
             " m/s towards " + fmt(deg(top.azimuth), 4) + " deg at z = " + fmt(top.z, 4) + " m" +
             (data.current.length > 1 ? " (" + data.current.length + " levels, arrows at their depths)" : ""));
  }
  if (data.waves.kind !== "none")
    envArrow(data.waves.azimuth, 0x00a0a0, 0.005 * sceneSize, "waves (" + data.waves.kind + ") " +
             fmt(data.waves.height, 3) + " m, " + fmt(data.waves.period, 3) + " s towards " +
             fmt(deg(data.waves.azimuth), 4) + " deg");
  if (data.wind.speed > 0)
    envArrow(data.wind.azimuth, 0x707070, 0.04 * sceneSize, "wind " + fmt(data.wind.speed, 3) + " m/s towards " +
             fmt(deg(data.wind.azimuth), 4) + " deg");
  var axes = new THREE.AxesHelper(0.08 * sceneSize);
  axes.position.set(box.min.x - 0.5 * margin, box.max.y + 0.5 * margin, 0);
  scene.add(axes);

  // Lines as tubes of their contact diameter (exaggerated on request: a 0.5 m riser 1 km long is a hair).
  var ring = 10;
  var maxDiam = 0, diams = [];
  data.lines.forEach(function (l) { l.diam.forEach(function (d) { maxDiam = Math.max(maxDiam, d); diams.push(d); }); });
  diams.sort(function (a, b) { return a - b; });
  // Automatic exaggeration: the thicker lines (75th percentile of the node diameters) about 1/600 of the scene.
  var typicalDiam = diams.length ? diams[Math.floor(0.75 * (diams.length - 1))] : 1;
  var exaggerations = [1, 2, 5, 10, 20, 50, 100];
  var autoEx = 1;
  for (var e = 0; e < exaggerations.length; ++e) {
    autoEx = exaggerations[e];
    if (typicalDiam * autoEx >= sceneSize / 600) break;
  }
  var exaggeration = autoEx;
  // Exaggerated tubes are at least this thick [m], so a chain beside a riser stays visible.
  var minRadius = sceneSize / 1500;
  var tubes = data.lines.map(function (line, li) {
    var n = line.arc.length;
    var g = new THREE.BufferGeometry();
    var pos = new Float32Array(n * ring * 3), nor = new Float32Array(n * ring * 3), col = new Float32Array(n * ring * 3);
    var index = [];
    for (var i = 0; i + 1 < n; ++i)
      for (var k = 0; k < ring; ++k) {
        var a = i * ring + k, b = i * ring + (k + 1) % ring, c = a + ring, d = b + ring;
        index.push(a, c, b, b, c, d);
      }
    g.setIndex(index);
    g.setAttribute("position", new THREE.BufferAttribute(pos, 3));
    g.setAttribute("normal", new THREE.BufferAttribute(nor, 3));
    g.setAttribute("color", new THREE.BufferAttribute(col, 3));
    var mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors, side: THREE.DoubleSide }));
    mesh.frustumCulled = false;
    mesh.userData.line = li;
    scene.add(mesh);
    return mesh;
  });
  function updateTube(li, fl) {
    var g = tubes[li].geometry, pos = g.attributes.position.array, nor = g.attributes.normal.array;
    var p = fl.p, n = p.length / 3, diam = data.lines[li].diam;
    var t = new THREE.Vector3(), nrm = new THREE.Vector3(), bin = new THREE.Vector3(), tmp = new THREE.Vector3();
    var first = true;
    for (var i = 0; i < n; ++i) {
      var i0 = Math.max(0, i - 1), i1 = Math.min(n - 1, i + 1);
      t.set(p[3 * i1] - p[3 * i0], p[3 * i1 + 1] - p[3 * i0 + 1], p[3 * i1 + 2] - p[3 * i0 + 2]);
      if (t.lengthSq() === 0) t.set(0, 0, 1);
      t.normalize();
      if (!first) nrm.addScaledVector(t, -nrm.dot(t));
      if (first || nrm.lengthSq() < 1e-8) {
        tmp.set(Math.abs(t.z) < 0.9 ? 0 : 1, 0, Math.abs(t.z) < 0.9 ? 1 : 0);
        nrm.crossVectors(t, tmp);
        first = false;
      }
      nrm.normalize();
      bin.crossVectors(t, nrm);
      var r = 0.5 * diam[i] * exaggeration;
      if (exaggeration > 1) r = Math.max(r, minRadius);
      for (var k = 0; k < ring; ++k) {
        var ang = 2 * Math.PI * k / ring, c = Math.cos(ang), s = Math.sin(ang);
        var nx = c * nrm.x + s * bin.x, ny = c * nrm.y + s * bin.y, nz = c * nrm.z + s * bin.z;
        var o = 3 * (i * ring + k);
        pos[o] = p[3 * i] / 1000 + r * nx; pos[o + 1] = p[3 * i + 1] / 1000 + r * ny; pos[o + 2] = p[3 * i + 2] / 1000 + r * nz;
        nor[o] = nx; nor[o + 1] = ny; nor[o + 2] = nz;
      }
    }
    g.attributes.position.needsUpdate = true;
    g.attributes.normal.needsUpdate = true;
  }
  var quantity = quantities[0];
  function colourTube(li, fl) {
    var col = tubes[li].geometry.attributes.color.array, n = fl.p.length / 3, rgb = [0, 0, 0];
    var v = quantity.key === "line" ? null : fl[quantity.key];
    var base = new THREE.Color(lineColour(li));
    for (var i = 0; i < n; ++i) {
      if (v && v[i] !== null && v[i] !== undefined) {
        var u = (v[i] - quantity.min) / (quantity.max - quantity.min);
        colourMap(quantity.reversed ? 1 - u : u, rgb);
      } else if (v) {
        rgb[0] = rgb[1] = rgb[2] = 0.6;
      } else {
        rgb[0] = base.r; rgb[1] = base.g; rgb[2] = base.b;
      }
      for (var k = 0; k < ring; ++k) {
        var o = 3 * (i * ring + k);
        col[o] = rgb[0]; col[o + 1] = rgb[1]; col[o + 2] = rgb[2];
      }
    }
    tubes[li].geometry.attributes.color.needsUpdate = true;
  }

  // Vessels: boxes from -draft to +draft/2 about the reference point, in vessel axes (x forward).
  var vessels = data.vessels.map(function (v) {
    var group = new THREE.Group();
    if (v.hull && v.hull.length) {
      // Its hull's contact shapes (vessels[].hull), vessel axes: boxes, cylinders, capsules.
      var material = new THREE.MeshLambertMaterial({ color: 0xb0b4bb, transparent: true, opacity: 0.75 });
      var edgeMaterial = new THREE.LineBasicMaterial({ color: 0x303030 });
      v.hull.forEach(function (h) {
        var parts = [];
        if (h.kind === "box") {
          var box = new THREE.Mesh(new THREE.BoxBufferGeometry(h.s[0], h.s[1], h.s[2]), material);
          box.position.set(h.c[0], h.c[1], h.c[2]);
          parts.push({ mesh: box, edges: true });
        } else {
          var a = new THREE.Vector3(h.a[0], h.a[1], h.a[2]), b = new THREE.Vector3(h.b[0], h.b[1], h.b[2]);
          var axis = new THREE.Vector3().subVectors(b, a), length = axis.length(), r = 0.5 * h.d;
          if (length > 0) {
            // three.js cylinders stand along +y: turn +y onto the shape's axis.
            var cyl = new THREE.Mesh(new THREE.CylinderBufferGeometry(r, r, length, 24), material);
            cyl.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis.clone().normalize());
            cyl.position.copy(a).addScaledVector(axis, 0.5);
            parts.push({ mesh: cyl, edges: true });
          }
          if (h.kind === "capsule")
            [a, b].forEach(function (end) {
              var ball = new THREE.Mesh(new THREE.SphereBufferGeometry(r, 16, 12), material);
              ball.position.copy(end);
              parts.push({ mesh: ball, edges: false });
            });
        }
        parts.forEach(function (part) {
          var m = part.mesh;
          group.add(m);
          if (part.edges) {
            var edges = new THREE.LineSegments(new THREE.EdgesGeometry(m.geometry, 30), edgeMaterial);
            edges.position.copy(m.position);
            edges.quaternion.copy(m.quaternion);
            group.add(edges);
          }
        });
      });
      scene.add(group);
      return group;
    }
    var g = new THREE.BoxBufferGeometry(v.length, v.breadth, 1.5 * v.draft);
    var m = new THREE.Mesh(g, new THREE.MeshLambertMaterial({ color: 0xb0b4bb, transparent: true, opacity: 0.75 }));
    m.position.z = -0.25 * v.draft;
    group.add(m);
    var edges = new THREE.LineSegments(new THREE.EdgesGeometry(g), new THREE.LineBasicMaterial({ color: 0x303030 }));
    edges.position.z = m.position.z;
    group.add(edges);
    // Bow marker.
    var bow = new THREE.Mesh(new THREE.ConeBufferGeometry(0.12 * v.breadth, 0.15 * v.length, 12),
                             new THREE.MeshLambertMaterial({ color: 0xe0a020 }));
    bow.rotation.z = -Math.PI / 2;
    bow.position.set(0.5 * v.length + 0.075 * v.length, 0, 0.5 * v.draft);
    group.add(bow);
    scene.add(group);
    return group;
  });
  // Name labels (sprites that always face the camera).
  function label(text, colour) {
    var c = document.createElement("canvas"), ctx = c.getContext("2d");
    ctx.font = "bold 28px sans-serif";
    c.width = Math.ceil(ctx.measureText(text).width) + 12;
    c.height = 36;
    ctx.font = "bold 28px sans-serif";
    ctx.fillStyle = "rgba(255,255,255,0.75)";
    ctx.fillRect(0, 0, c.width, c.height);
    ctx.fillStyle = colour;
    ctx.fillText(text, 6, 28);
    var tex = new THREE.CanvasTexture(c);
    tex.minFilter = THREE.LinearFilter;
    var sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: tex, depthTest: false }));
    var h = 0.025 * sceneSize;
    sprite.scale.set(h * c.width / c.height, h, 1);
    sprite.renderOrder = 10;
    return sprite;
  }
  var showLabels = true;
  var vesselLabels = data.vessels.map(function (v) {
    var s = label(v.name, "#303030");
    scene.add(s);
    return s;
  });
  var lineLabels = data.lines.map(function (l, i) {
    var s = label(l.name, lineColour(i));
    scene.add(s);
    return s;
  });
  function placeLabels(f) {
    f.v.forEach(function (pose, vi) {
      vesselLabels[vi].position.set(pose[0], pose[1], pose[2] + 0.6 * data.vessels[vi].draft + 0.03 * sceneSize);
      vesselLabels[vi].visible = showLabels;
    });
    f.lines.forEach(function (fl, li) {
      var i = Math.floor(0.5 * (fl.p.length / 3 - 1));
      lineLabels[li].position.set(fl.p[3 * i] / 1000, fl.p[3 * i + 1] / 1000, fl.p[3 * i + 2] / 1000 + 0.02 * sceneSize);
      lineLabels[li].visible = showLabels;
    });
  }
  function placeVessel(vi, pose) {
    var g = vessels[vi], r = new THREE.Vector3(pose[3], pose[4], pose[5]), angle = r.length();
    g.position.set(pose[0], pose[1], pose[2]);
    if (angle > 0) g.quaternion.setFromAxisAngle(r.divideScalar(angle), angle);
    else g.quaternion.set(0, 0, 0, 1);
  }

  // Contact points (spheres on both lines) and forces (arrows from line B to line A, length by force).
  var maxForce = 0;
  frames.forEach(function (f) { f.k.forEach(function (c) { maxForce = Math.max(maxForce, c[8]); }); });
  var contactGroup = new THREE.Group();
  scene.add(contactGroup);
  var contactMaterial = new THREE.MeshLambertMaterial({ color: 0xff2020 });
  var sphereGeometry = new THREE.SphereBufferGeometry(1, 12, 8);
  function drawContacts(f) {
    while (contactGroup.children.length) contactGroup.remove(contactGroup.children[0]);
    var radius = Math.max(typicalDiam * exaggeration * 1.5, sceneSize / 300);
    f.k.forEach(function (c) {
      var a = new THREE.Vector3(c[2], c[3], c[4]), b = new THREE.Vector3(c[5], c[6], c[7]);
      [a, b].forEach(function (p) {
        var s = new THREE.Mesh(sphereGeometry, contactMaterial);
        s.scale.setScalar(radius);
        s.position.copy(p);
        contactGroup.add(s);
      });
      var dir = a.clone().sub(b);
      if (dir.lengthSq() < 1e-12) dir.set(0, 0, 1);
      dir.normalize();
      var len = 0.12 * sceneSize * (maxForce > 0 ? c[8] / maxForce : 0) + 4 * radius;
      contactGroup.add(new THREE.ArrowHelper(dir, a, len, 0xff0000, 0.3 * len, 0.15 * len));
    });
  }

  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  camera.position.set(centre.x - 0.9 * sceneSize, centre.y - 1.3 * sceneSize, centre.z + 0.7 * sceneSize);
  camera.near = sceneSize / 1e4;
  camera.far = sceneSize * 100;
  controls.update();
  var dirty = true;
  controls.addEventListener("change", function () { dirty = true; });
  function resize() {
    var w = container.clientWidth, h = container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    dirty = true;
  }
  window.addEventListener("resize", resize);
  resize();

  // Hover over a tube: line, node arc length and the values there.
  var raycaster = new THREE.Raycaster(), mouse = new THREE.Vector2(), hoverBox = document.getElementById("hover");
  renderer.domElement.addEventListener("mousemove", function (ev) {
    var r = renderer.domElement.getBoundingClientRect();
    mouse.set((ev.clientX - r.left) / r.width * 2 - 1, -(ev.clientY - r.top) / r.height * 2 + 1);
    raycaster.setFromCamera(mouse, camera);
    var hit = raycaster.intersectObjects(tubes)[0];
    if (!hit || !frames.length) { hoverBox.textContent = ""; return; }
    var li = hit.object.userData.line, node = Math.floor(hit.face.a / ring);
    var fl = frames[frameIndex].lines[li], line = data.lines[li];
    node = Math.min(node, line.arc.length - 1);
    var parts = [line.name + ", s = " + fmt(line.arc[node], 6) + " m",
                 "z = " + fmt(fl.p[3 * node + 2] / 1000, 5) + " m"];
    quantities.forEach(function (q) {
      if (q.key === "line" || !fl[q.key]) return;
      var v = fl[q.key][node];
      if (q.clearance && v === null && isFinite(data.clearanceMargin))
        parts.push(q.label + " > " + fmt(data.clearanceMargin, 4) + " " + q.unit + " (beyond the margin)");
      else parts.push(q.label + " " + fmt(v, 4) + " " + q.unit);
    });
    hoverBox.textContent = parts.join(" \u00b7 ");
  });

  // ---------------------------------------------------------------- legend
  function drawLegend() {
    var L = document.getElementById("legend");
    L.innerHTML = "";
    if (quantity.key === "line") {
      data.lines.forEach(function (l, i) {
        var d = el("div");
        d.innerHTML = "<span style='color:" + lineColour(i) + "'>\u25a0</span> ";
        d.appendChild(document.createTextNode(l.name));
        L.appendChild(d);
      });
    } else {
      L.appendChild(el("div", null, quantity.label + " (" + quantity.unit + ")"));
      var c = el("canvas", { width: 160, height: 14 }), ctx = c.getContext("2d"), rgb = [0, 0, 0];
      for (var x = 0; x < 160; ++x) {
        colourMap(quantity.reversed ? 1 - x / 159 : x / 159, rgb);
        ctx.fillStyle = "rgb(" + rgb.map(function (v) { return Math.round(255 * v); }).join(",") + ")";
        ctx.fillRect(x, 0, 1, 14);
      }
      L.appendChild(c);
      var ticks = el("div");
      ticks.style.display = "flex";
      ticks.style.justifyContent = "space-between";
      ticks.appendChild(el("span", null, fmt(quantity.min, 4)));
      ticks.appendChild(el("span", null, fmt(0.5 * (quantity.min + quantity.max), 4)));
      ticks.appendChild(el("span", null, (quantity.capped ? "\u2265 " : "") + fmt(quantity.max, 4)));
      L.appendChild(ticks);
      if (quantity.key === "c")
        L.appendChild(el("div", null, "grey: not assessed / beyond the margin" +
            (isFinite(data.clearanceMargin) ? " (" + fmt(data.clearanceMargin, 4) + " m)" : "")));
    }
    L.appendChild(el("div", null, exaggeration > 1 ? "tubes: contact diameter \u00d7" + exaggeration + ", at least " +
        fmt(2 * minRadius, 2) + " m" : "tubes: contact diameter to scale"));
    var extra = el("div");
    extra.innerHTML = envNotes.join("<br>");
    L.appendChild(extra);
    if (maxForce > 0) L.appendChild(el("div", null, "red arrows: contact force (longest " + fmt(maxForce / 1000, 4) + " kN)"));
  }

  // ---------------------------------------------------------------- replay
  var frameIndex = 0, playing = false, speed = 1, lastTick = null, simTime = frames.length ? frames[0].t : 0;
  var slider = document.getElementById("slider"), timeLabel = document.getElementById("time");
  slider.max = Math.max(0, frames.length - 1);
  var plots = [];
  function showFrame(i) {
    if (!frames.length) return;
    frameIndex = Math.max(0, Math.min(frames.length - 1, i));
    var f = frames[frameIndex];
    f.lines.forEach(function (fl, li) { updateTube(li, fl); colourTube(li, fl); });
    f.v.forEach(function (pose, vi) { placeVessel(vi, pose); });
    placeLabels(f);
    drawContacts(f);
    slider.value = frameIndex;
    timeLabel.textContent = isDynamic ? "t = " + f.t.toFixed(2) + " s (frame " + (frameIndex + 1) + " of " +
        frames.length + ")" : (data.kind === "view" ? "initial shapes" : staticsFailed ? "statics did not converge: where the solver stopped" :
         "static equilibrium");
    plots.forEach(function (p) { if (p.timeCursor) p.setCursor(f.t); });
    dirty = true;
  }
  function frameAt(t) {
    var lo = 0, hi = frames.length - 1;
    while (lo < hi) { var mid = (lo + hi + 1) >> 1; if (frames[mid].t <= t + 1e-9) lo = mid; else hi = mid - 1; }
    return lo;
  }
  slider.addEventListener("input", function () { simTime = frames[+slider.value].t; showFrame(+slider.value); });
  var playButton = document.getElementById("play");
  function setPlaying(on) {
    playing = on && frames.length > 1;
    playButton.textContent = playing ? "Pause" : "Play";
    lastTick = null;
  }
  playButton.addEventListener("click", function () {
    if (!playing && frameIndex === frames.length - 1) { simTime = frames[0].t; showFrame(0); }
    setPlaying(!playing);
  });
  var speedSelect = document.getElementById("speed");
  [0.1, 0.25, 0.5, 1, 2, 5, 10, 20].forEach(function (s) {
    var o = el("option", { value: s }, s + "\u00d7");
    if (s === 1) o.selected = true;
    speedSelect.appendChild(o);
  });
  speedSelect.addEventListener("change", function () { speed = +speedSelect.value; });
  if (!isDynamic) { playButton.disabled = true; speedSelect.disabled = true; slider.disabled = true; }
  var qSelect = document.getElementById("quantity");
  quantities.forEach(function (q, i) { qSelect.appendChild(el("option", { value: i }, q.label + (q.unit ? " (" + q.unit + ")" : ""))); });
  qSelect.addEventListener("change", function () { quantity = quantities[+qSelect.value]; drawLegend(); showFrame(frameIndex); });
  var exSelect = document.getElementById("exaggeration");
  exaggerations.forEach(function (x) {
    var o = el("option", { value: x }, x === 1 ? "true scale" : "\u00d7" + x);
    if (x === exaggeration) o.selected = true;
    exSelect.appendChild(o);
  });
  var labelBox = document.getElementById("labels");
  labelBox.addEventListener("change", function () { showLabels = labelBox.checked; showFrame(frameIndex); });
  exSelect.addEventListener("change", function () { exaggeration = +exSelect.value; drawLegend(); showFrame(frameIndex); });
  var d = data.decimation || {};
  document.getElementById("note").textContent = isDynamic ?
      frames.length + " frames of " + d.outputs + " output times (" + (d.stride > 1 ? "every " + d.stride +
      " output times" : "every output time") + ", output interval " + d.output_interval + " s); the plots use every output time." :
      (data.kind === "view" ? "The model before any analysis: initial shapes of the lines." :
       staticsFailed ? "The static solve did not converge: the shape and results shown are where it stopped, not " +
       "an equilibrium (see the run log)." : "Statics only: the static equilibrium.");
  function tick(now) {
    if (playing && frames.length > 1) {
      if (lastTick !== null) {
        simTime += (now - lastTick) / 1000 * speed;
        if (simTime >= frames[frames.length - 1].t) { simTime = frames[frames.length - 1].t; setPlaying(false); }
        var i = frameAt(simTime);
        if (i !== frameIndex) showFrame(i);
      }
      lastTick = now;
    }
    if (dirty) { controls.update(); renderer.render(scene, camera); dirty = false; }
    requestAnimationFrame(tick);
  }

  // ---------------------------------------------------------------- plots (SVG, zoom by drag and wheel)
  var svgNS = "http://www.w3.org/2000/svg";
  function svgEl(tag, attrs) {
    var e = document.createElementNS(svgNS, tag);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    return e;
  }
  function niceTicks(lo, hi, n) {
    var span = hi - lo, step = Math.pow(10, Math.floor(Math.log10(span / n))), err = span / n / step;
    step *= err >= 7.5 ? 10 : err >= 3.5 ? 5 : err >= 1.5 ? 2 : 1;
    var out = [];
    for (var v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) out.push(Math.abs(v) < 1e-12 * step ? 0 : v);
    return out;
  }
  // opts: title, xlabel, ylabel, series [{name, x, y, colour, dash}], timeCursor, equalAxes
  function makePlot(opts) {
    var div = el("div", { "class": "plot" });
    div.appendChild(el("h3", null, opts.title));
    var W = 560, H = 280, ml = 62, mr = 12, mt = 8, mb = 40;
    var svg = svgEl("svg", { viewBox: "0 0 " + W + " " + H, preserveAspectRatio: "none" });
    div.appendChild(svg);
    var readout = el("div", { "class": "readout" });
    div.appendChild(readout);
    div.appendChild(el("div", { "class": "hint" }, "drag: zoom to box \u00b7 wheel: zoom \u00b7 double-click: reset"));
    document.getElementById("plot-grid").appendChild(div);
    var full = { x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity };
    opts.series.forEach(function (s) {
      for (var i = 0; i < s.x.length; ++i) {
        if (s.x[i] === null || s.y[i] === null || !isFinite(s.x[i]) || !isFinite(s.y[i])) continue;
        full.x0 = Math.min(full.x0, s.x[i]); full.x1 = Math.max(full.x1, s.x[i]);
        full.y0 = Math.min(full.y0, s.y[i]); full.y1 = Math.max(full.y1, s.y[i]);
      }
    });
    if (!isFinite(full.x0)) { full = { x0: 0, x1: 1, y0: 0, y1: 1 }; }
    function pad(a, b) { var s = b - a; if (s <= 0) s = Math.max(Math.abs(a) * 0.1, 1e-9); return [a - 0.05 * s, b + 0.05 * s]; }
    var px = pad(full.x0, full.x1), py = pad(full.y0, full.y1);
    if (opts.equalAxes) {
      var sx = px[1] - px[0], sy = py[1] - py[0], k = (W - ml - mr) / (H - mt - mb);
      if (sx / sy > k) { var cy = 0.5 * (py[0] + py[1]); py = [cy - 0.5 * sx / k, cy + 0.5 * sx / k]; }
      else { var cx = 0.5 * (px[0] + px[1]); px = [cx - 0.5 * sy * k, cx + 0.5 * sy * k]; }
    }
    var home = { x0: px[0], x1: px[1], y0: py[0], y1: py[1] }, view = Object.assign({}, home);
    function X(v) { return ml + (v - view.x0) / (view.x1 - view.x0) * (W - ml - mr); }
    function Y(v) { return H - mb - (v - view.y0) / (view.y1 - view.y0) * (H - mt - mb); }
    function invX(px_) { return view.x0 + (px_ - ml) / (W - ml - mr) * (view.x1 - view.x0); }
    function invY(py_) { return view.y0 + (H - mb - py_) / (H - mt - mb) * (view.y1 - view.y0); }
    var plot = { timeCursor: opts.timeCursor, cursorT: null };
    var cursorLine = null, hoverG = null, zoomRect = null;
    function draw() {
      while (svg.firstChild) svg.removeChild(svg.firstChild);
      var clipId = "clip" + Math.random().toString(36).slice(2);
      var defs = svgEl("defs", {}), cp = svgEl("clipPath", { id: clipId });
      cp.appendChild(svgEl("rect", { x: ml, y: mt, width: W - ml - mr, height: H - mt - mb }));
      defs.appendChild(cp);
      svg.appendChild(defs);
      niceTicks(view.x0, view.x1, 6).forEach(function (v) {
        svg.appendChild(svgEl("line", { x1: X(v), x2: X(v), y1: mt, y2: H - mb, stroke: "#eee" }));
        var t = svgEl("text", { x: X(v), y: H - mb + 14, "font-size": 11, "text-anchor": "middle" });
        t.textContent = fmt(v, 6);
        svg.appendChild(t);
      });
      niceTicks(view.y0, view.y1, 5).forEach(function (v) {
        svg.appendChild(svgEl("line", { x1: ml, x2: W - mr, y1: Y(v), y2: Y(v), stroke: "#eee" }));
        var t = svgEl("text", { x: ml - 4, y: Y(v) + 4, "font-size": 11, "text-anchor": "end" });
        t.textContent = fmt(v, 6);
        svg.appendChild(t);
      });
      svg.appendChild(svgEl("rect", { x: ml, y: mt, width: W - ml - mr, height: H - mt - mb, fill: "none", stroke: "#888" }));
      var xl = svgEl("text", { x: (ml + W - mr) / 2, y: H - 6, "font-size": 12, "text-anchor": "middle" });
      xl.textContent = opts.xlabel;
      svg.appendChild(xl);
      var yl = svgEl("text", { x: 12, y: (mt + H - mb) / 2, "font-size": 12, "text-anchor": "middle",
                               transform: "rotate(-90 12 " + (mt + H - mb) / 2 + ")" });
      yl.textContent = opts.ylabel;
      svg.appendChild(yl);
      var g = svgEl("g", { "clip-path": "url(#" + clipId + ")" });
      opts.series.forEach(function (s) {
        var dpath = "", pen = false;
        // Thin out to about two points per pixel column for long series.
        var step = Math.max(1, Math.floor(s.x.length / 2000));
        for (var i = 0; i < s.x.length; i += step) {
          if (s.y[i] === null || !isFinite(s.y[i])) { pen = false; continue; }
          dpath += (pen ? "L" : "M") + X(s.x[i]).toFixed(1) + " " + Y(s.y[i]).toFixed(1);
          pen = true;
        }
        var attrs = { d: dpath, fill: "none", stroke: s.colour, "stroke-width": 1.4 };
        if (s.dash) attrs["stroke-dasharray"] = s.dash;
        g.appendChild(svgEl("path", attrs));
      });
      svg.appendChild(g);
      // Legend.
      var lx = ml + 8, ly = mt + 10;
      opts.series.forEach(function (s) {
        var w = 24 + 6.2 * s.name.length;
        if (lx + w > W - mr && lx > ml + 8) { lx = ml + 8; ly += 14; }
        var t = svgEl("text", { x: lx + 16, y: ly + 4, "font-size": 11 });
        t.textContent = s.name;
        svg.appendChild(svgEl("line", { x1: lx, x2: lx + 13, y1: ly, y2: ly, stroke: s.colour,
                                        "stroke-width": 2, "stroke-dasharray": s.dash || "" }));
        svg.appendChild(t);
        lx += w;
      });
      cursorLine = svgEl("line", { x1: 0, x2: 0, y1: mt, y2: H - mb, stroke: "#000", "stroke-dasharray": "3 3",
                                   visibility: "hidden" });
      svg.appendChild(cursorLine);
      hoverG = svgEl("g", {});
      svg.appendChild(hoverG);
      zoomRect = svgEl("rect", { fill: "#1d355722", stroke: "#1d3557", visibility: "hidden" });
      svg.appendChild(zoomRect);
      plot.setCursor(plot.cursorT);
    }
    plot.setCursor = function (t) {
      plot.cursorT = t;
      if (!cursorLine) return;
      if (t === null || t < view.x0 || t > view.x1) { cursorLine.setAttribute("visibility", "hidden"); return; }
      cursorLine.setAttribute("x1", X(t)); cursorLine.setAttribute("x2", X(t));
      cursorLine.setAttribute("visibility", "visible");
    };
    function svgPoint(ev) {
      var r = svg.getBoundingClientRect();
      return [(ev.clientX - r.left) / r.width * W, (ev.clientY - r.top) / r.height * H];
    }
    var dragStart = null;
    svg.addEventListener("mousedown", function (ev) { dragStart = svgPoint(ev); ev.preventDefault(); });
    svg.addEventListener("mousemove", function (ev) {
      var p = svgPoint(ev);
      if (dragStart) {
        zoomRect.setAttribute("x", Math.min(p[0], dragStart[0])); zoomRect.setAttribute("y", Math.min(p[1], dragStart[1]));
        zoomRect.setAttribute("width", Math.abs(p[0] - dragStart[0])); zoomRect.setAttribute("height", Math.abs(p[1] - dragStart[1]));
        zoomRect.setAttribute("visibility", "visible");
        return;
      }
      // Hover: the nearest point of each series (in screen distance).
      while (hoverG.firstChild) hoverG.removeChild(hoverG.firstChild);
      var parts = [];
      opts.series.forEach(function (s) {
        var best = -1, bd = Infinity;
        for (var i = 0; i < s.x.length; ++i) {
          if (s.y[i] === null || !isFinite(s.y[i])) continue;
          var dx = X(s.x[i]) - p[0], dy = opts.byDistance ? Y(s.y[i]) - p[1] : 0, dd = dx * dx + dy * dy;
          if (dd < bd) { bd = dd; best = i; }
        }
        if (best < 0) return;
        hoverG.appendChild(svgEl("circle", { cx: X(s.x[best]), cy: Y(s.y[best]), r: 3.5, fill: s.colour }));
        parts.push(s.name + ": " + opts.xlabel.split(" (")[0] + " " + fmt(s.x[best], 6) + ", " + fmt(s.y[best], 5));
      });
      readout.textContent = parts.join("  |  ");
    });
    window.addEventListener("mouseup", function (ev) {
      if (!dragStart) return;
      var p = svgPoint(ev), a = dragStart;
      dragStart = null;
      zoomRect.setAttribute("visibility", "hidden");
      if (Math.abs(p[0] - a[0]) < 5 || Math.abs(p[1] - a[1]) < 5) return;
      var nx0 = invX(Math.min(a[0], p[0])), nx1 = invX(Math.max(a[0], p[0]));
      var ny0 = invY(Math.max(a[1], p[1])), ny1 = invY(Math.min(a[1], p[1]));
      view = { x0: nx0, x1: nx1, y0: ny0, y1: ny1 };
      draw();
    });
    svg.addEventListener("wheel", function (ev) {
      ev.preventDefault();
      var p = svgPoint(ev), f = ev.deltaY > 0 ? 1.25 : 0.8, cx = invX(p[0]), cy = invY(p[1]);
      view = { x0: cx + (view.x0 - cx) * f, x1: cx + (view.x1 - cx) * f, y0: cy + (view.y0 - cy) * f, y1: cy + (view.y1 - cy) * f };
      draw();
    }, { passive: false });
    svg.addEventListener("dblclick", function () { view = Object.assign({}, home); draw(); });
    svg.addEventListener("mouseleave", function () { readout.textContent = ""; if (hoverG) while (hoverG.firstChild) hoverG.removeChild(hoverG.firstChild); });
    draw();
    plots.push(plot);
    return plot;
  }

  var h = data.history || { t: [] };
  if (h.t.length) {
    var series = [];
    data.lines.forEach(function (l, i) {
      series.push({ name: l.name + " A", x: h.t, y: h.endTension[2 * i], colour: lineColour(i) });
      series.push({ name: l.name + " B", x: h.t, y: h.endTension[2 * i + 1], colour: lineColour(i), dash: "5 3" });
    });
    makePlot({ title: "End tensions", xlabel: "time (s)", ylabel: "tension (kN)", series: series, timeCursor: true });
  }
  [["T", "Effective tension", "tension (kN)"], ["M", "Bending moment", "bending moment (kN m)"]].forEach(function (q) {
    if (!data.ranges || !data.ranges.length || data.kind === "view") return;
    var series = [];
    data.ranges.forEach(function (r, i) {
      if (!r) return;
      var arc = data.lines[i].arc, same = isDynamic ? false : true;
      series.push({ name: data.lines[i].name + (same ? "" : " max"), x: arc, y: r[q[0] + "max"], colour: lineColour(i) });
      if (!same) series.push({ name: data.lines[i].name + " min", x: arc, y: r[q[0] + "min"], colour: lineColour(i), dash: "5 3" });
    });
    if (q[0] === "M" && series.every(function (s) { return s.y.every(function (v) { return !v; }); })) return;
    makePlot({ title: q[1] + (isDynamic ? ": range graph (every time step)" :
                                staticsFailed ? ": where the static solve stopped" : ": static equilibrium"),
               xlabel: "arc length from end A (m)", ylabel: q[2], series: series });
  });
  if (data.clash && data.clash.t && data.clash.t.length) {
    makePlot({ title: "Minimum clearance between lines", xlabel: "time (s)", ylabel: "clearance (m)", timeCursor: true,
               series: data.clash.pairs.map(function (p, i) {
                 return { name: p[0] + " / " + p[1], x: data.clash.t, y: data.clash.clearance[i], colour: lineColour(i) };
               }) });
  }
  if (data.envelope && data.envelope.length) {
    var es = [];
    data.envelope.forEach(function (s, i) {
      var name = data.lines[s.line].name + " to " + data.lines[s.other].name;
      es.push({ name: name + " static", x: data.lines[s.line].arc, y: s.static, colour: lineColour(i), dash: "5 3" });
      if (s.dynamic.some(function (v) { return v !== null; }))
        es.push({ name: name + " dynamic min", x: data.lines[s.line].arc, y: s.dynamic, colour: lineColour(i) });
    });
    makePlot({ title: "Clearance envelope", xlabel: "arc length (m)", ylabel: "clearance (m)", series: es });
  }
  // Weibull plot of the peaks of each line's end B tension: ln(-ln(1 - F)) against ln(excess over the mean),
  // F = i / (n + 1); a Weibull distribution is a straight line of slope shape (Rayleigh: 2).
  (data.peakFits || []).forEach(function (p) {
    var a = p.peaks.map(function (v) { return (v - p.mean) / 1000; }).filter(function (v) { return v > 0; }).sort(function (x, y) { return x - y; });
    if (a.length < 3) return;
    var n = a.length, xs = a.map(Math.log), ys = a.map(function (_, i) { return Math.log(-Math.log(1 - (i + 1) / (n + 1))); });
    var x0 = xs[0] - 0.2, x1 = xs[n - 1] + 0.2;
    function line(fit) {  // y = shape (x - ln(scale / 1 kN))
      var c = Math.log(fit[0] / 1000);
      return { x: [x0, x1], y: [fit[1] * (x0 - c), fit[1] * (x1 - c)] };
    }
    var r = line(p.rayleigh), w = line(p.weibull);
    makePlot({ title: data.lines[p.line].name + " end B tension peaks: Weibull plot of the fits", xlabel: "ln(peak - mean, kN)",
               ylabel: "ln(-ln(1 - F))", series: [
                 { name: "peaks", x: xs, y: ys, colour: "#333", dash: "1 4" },
                 { name: "Rayleigh", x: r.x, y: r.y, colour: lineColour(0) },
                 { name: "Weibull (shape " + p.weibull[1].toFixed(2) + ")", x: w.x, y: w.y, colour: lineColour(1), dash: "5 3" }] });
  });
  if (data.fatigue && data.fatigue.length) {
    makePlot({ title: "Fatigue damage per year (log10)", xlabel: "arc length from end A (m)",
               ylabel: "log10 damage per year", series: data.fatigue.map(function (f, i) {
                 return { name: data.lines[f.line].name, x: f.arc, colour: lineColour(f.line),
                          y: f.damage.map(function (d) { return d > 0 ? Math.log10(d) : null; }) };
               }) });
  }
  if (data.clashDamage && data.clashDamage.some(function (c) { return c.impacts.some(function (n) { return n > 0; }); })) {
    makePlot({ title: "Clash damage: impact energy per bin", xlabel: "arc length from end A (m)",
               ylabel: "accumulated impact energy (J)", series: data.clashDamage.map(function (c) {
                 return { name: data.lines[c.line].name, x: c.arc, y: c.energy, colour: lineColour(c.line) };
               }) });
  }
  if (data.vessels.length && h.vesselXY && h.vesselXY.length && h.t.length) {
    makePlot({ title: "Vessel drift path (plan view)", xlabel: "x (m)", ylabel: "y (m)", equalAxes: true, byDistance: true,
               series: data.vessels.map(function (v, i) {
                 return { name: v.name, x: h.vesselXY[2 * i], y: h.vesselXY[2 * i + 1], colour: lineColour(i + 3) };
               }) });
  }
  if (!plots.length) document.getElementById("plot-grid").appendChild(el("p", null, "No plots: no analysis results."));

  // ---------------------------------------------------------------- clash table
  var clashRows = 0;
  (function clashTable() {
    var body = document.getElementById("clash-body");
    var events = data.clash && data.clash.events ? data.clash.events : [];
    if (!events.length) {
      body.appendChild(el("p", null, data.kind === "view" ? "Model view: no analysis yet." :
          data.clash ? "No contact events." : "No line contact in this model (or no dynamics)."));
      return;
    }
    body.appendChild(el("p", null, "Click a row to replay the event; click a header to sort."));
    var cols = [
      ["#", function (e, i) { return i + 1; }],
      ["lines", function (e) { return data.lines[e.a].name + " / " + data.lines[e.b].name; }, true],
      ["kind", function (e) { return e.kind; }, true],
      ["start (s)", function (e) { return e.start; }], ["end (s)", function (e) { return e.end; }],
      ["peak force (kN)", function (e) { return e.peak / 1000; }], ["impulse (N s)", function (e) { return e.impulse; }],
      ["impact speed (m/s)", function (e) { return e.speed; }], ["impact energy (J)", function (e) { return e.energy === null ? "" : e.energy; }],
      ["arc A (m)", function (e) { return e.arcA; }], ["arc B (m)", function (e) { return e.arcB; }],
      ["x (m)", function (e) { return e.pos[0]; }], ["y (m)", function (e) { return e.pos[1]; }],
      ["z (m)", function (e) { return e.pos[2]; }]];
    var table = el("table"), thead = el("thead"), hr = el("tr"), tbody = el("tbody");
    var rows = events.map(function (e, i) { return { e: e, v: cols.map(function (c) { return c[1](e, i); }) }; });
    var sortCol = 0, sortDir = 1;
    function fill() {
      while (tbody.firstChild) tbody.removeChild(tbody.firstChild);
      rows.sort(function (a, b) {
        var x = a.v[sortCol], y = b.v[sortCol];
        return (x < y ? -1 : x > y ? 1 : 0) * sortDir;
      });
      rows.forEach(function (r) {
        var tr = el("tr", { "data-start": r.e.start });
        r.v.forEach(function (v, c) { tr.appendChild(el("td", cols[c][2] ? { "class": "text" } : null, typeof v === "number" ? fmt(v, 5) : v)); });
        tr.addEventListener("click", function () {
          Array.prototype.forEach.call(tbody.children, function (x) { x.classList.remove("selected"); });
          tr.classList.add("selected");
          setPlaying(false);
          simTime = r.e.start;
          showFrame(frameAt(r.e.start));
          document.getElementById("view").scrollIntoView({ behavior: "smooth" });
        });
        tbody.appendChild(tr);
      });
    }
    cols.forEach(function (c, k) {
      var th = el("th", c[2] ? { "class": "text" } : null, c[0]);
      th.addEventListener("click", function () { sortDir = sortCol === k ? -sortDir : 1; sortCol = k; fill(); });
      hr.appendChild(th);
    });
    thead.appendChild(hr);
    table.appendChild(thead);
    table.appendChild(tbody);
    fill();
    body.appendChild(table);
    clashRows = rows.length;
  })();

  // ---------------------------------------------------------------- impacts on hulls and the seabed
  var impactRows = 0;
  (function impactTable() {
    var impacts = data.impacts || [];
    if (!impacts.length) return;
    var body = document.getElementById("clash-body");
    body.appendChild(el("h3", null, "Impacts on vessels' hulls and on the seabed"));
    body.appendChild(el("p", null, "Energy 1/2 m v0^2: m the two hulls' effective mass with added mass (hull on " +
        "hull), the Eq. 5 mass (line on hull, line on seabed). Click a row to replay the impact."));
    var cols = [
      ["bodies", function (e) { return e.bodies; }, true], ["kind", function (e) { return e.kind; }, true],
      ["start (s)", function (e) { return e.start; }], ["end (s)", function (e) { return e.end; }],
      ["peak force (kN)", function (e) { return e.peak / 1000; }], ["impulse (N s)", function (e) { return e.impulse; }],
      ["impact speed (m/s)", function (e) { return e.speed; }],
      ["rebound speed (m/s)", function (e) { return e.rebound === null ? "" : e.rebound; }],
      ["impact energy (J)", function (e) { return e.energy === null ? "" : e.energy; }],
      ["mass (kg)", function (e) { return e.mass === null ? "" : e.mass; }],
      ["x (m)", function (e) { return e.pos[0]; }], ["y (m)", function (e) { return e.pos[1]; }],
      ["z (m)", function (e) { return e.pos[2]; }]];
    var table = el("table", { "id": "impact-table" }), thead = el("thead"), hr = el("tr"), tbody = el("tbody");
    cols.forEach(function (c) { hr.appendChild(el("th", c[2] ? { "class": "text" } : null, c[0])); });
    thead.appendChild(hr);
    impacts.slice().sort(function (a, b) { return a.start - b.start; }).forEach(function (e) {
      var tr = el("tr", { "data-start": e.start });
      cols.forEach(function (c) {
        var v = c[1](e);
        tr.appendChild(el("td", c[2] ? { "class": "text" } : null, typeof v === "number" ? fmt(v, 5) : v));
      });
      tr.addEventListener("click", function () {
        setPlaying(false);
        simTime = e.start;
        showFrame(frameAt(e.start));
        document.getElementById("view").scrollIntoView({ behavior: "smooth" });
      });
      tbody.appendChild(tr);
    });
    table.appendChild(thead);
    table.appendChild(tbody);
    body.appendChild(table);
    impactRows = impacts.length;
  })();

  // ---------------------------------------------------------------- start, and the test hooks
  drawLegend();
  showFrame(0);
  controls.update();
  renderer.render(scene, camera);
  requestAnimationFrame(tick);

  function checksum() {
    var s = 0;
    tubes.forEach(function (m) { var a = m.geometry.attributes.position.array; for (var i = 0; i < a.length; ++i) s += Math.abs(a[i]) * ((i % 7) + 1); });
    return s;
  }
  function drawnPixels() {
    var gl = renderer.getContext(), w = gl.drawingBufferWidth, hh = gl.drawingBufferHeight;
    var px = new Uint8Array(w * hh * 4), count = 0;
    gl.readPixels(0, 0, w, hh, gl.RGBA, gl.UNSIGNED_BYTE, px);
    for (var i = 0; i < px.length; i += 4) if (Math.abs(px[i] - 0xdf) + Math.abs(px[i + 1] - 0xe8) + Math.abs(px[i + 2] - 0xf0) > 30) ++count;
    return count;
  }
  status.frames = frames.length;
  status.meshes = tubes.length;
  status.vessels = vessels.length;
  status.clashRows = clashRows;
  status.impactRows = impactRows;
  status.plots = plots.length;
  status.quantities = quantities.map(function (q) { return q.key; });
  status.checksumFirst = checksum();
  status.pixelsDrawn = drawnPixels();
  if (location.hash.indexOf("selftest") >= 0 && frames.length > 1) {
    // Move to the last frame through the slider's own input event, as a user does.
    slider.value = String(frames.length - 1);
    slider.dispatchEvent(new Event("input"));
    renderer.render(scene, camera);
    status.checksumSlider = checksum();
    status.contactsLast = contactGroup.children.length;
    // The same frame shown directly, from the first one.
    showFrame(0);
    showFrame(frames.length - 1);
    status.checksumLast = checksum();
    if (clashRows) {
      var all = document.querySelectorAll("#clash-body tbody tr"), row = all[all.length - 1];
      row.click();
      status.frameAfterRowClick = frameIndex;
      status.eventStart = +row.getAttribute("data-start");
      status.frameTimeAfterRowClick = frames[frameIndex].t;
    }
    showFrame(0);
    renderer.render(scene, camera);
    status.checksumBack = checksum();
  }
  // #t=SECONDS in the address opens the replay at that time (a link to an instant).
  var tm = /[#&]t=([0-9.eE+-]+)/.exec(location.hash);
  if (tm && frames.length > 1) { simTime = +tm[1]; showFrame(frameAt(simTime)); }
  status.openMs = Math.round(performance.now());  // navigation start to the first frame drawn
  status.ready = true;
  var st = document.getElementById("tangle-status");
  st.textContent = JSON.stringify(status);
  window.TANGLE_STATUS = status;
})();
