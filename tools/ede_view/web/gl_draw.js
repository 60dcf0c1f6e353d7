// ede-view's WebGL2 disk layer: every disk one point (gl.POINTS, gl_PointSize its diameter in pixels, at
// least one pixel), cut to a circle in the fragment shader, coloured from a palette uniform by its colour
// group. The frame's x, y, r, decoded to float32 by view.js, and its colour groups go to the GPU as they
// are (bufferData on the typed arrays), so the page's cost per frame is the upload and one draw call. Disks below a pixel are drawn as one pixel each: at 10^6 disks in 720 pixels that is the
// density view. In headless chromium without a GPU this runs on SwiftShader (software), still far
// cheaper on the page's main thread than the 2D canvas, whose pixels the main thread writes itself.
// Rejected: instanced quads (two triangles a disk: six times the vertices for the same circles; points
// suffice while a disk is under the implementation's largest point size, and larger disks fall back to
// the 2D canvas's arcs, see draw()); WebGL1 (no non-normalised byte attributes for the colour group).
'use strict';

function makeGlDisks(canvas) {
  const gl = canvas && canvas.getContext('webgl2', { antialias: false, alpha: false, preserveDrawingBuffer: true });
  if (!gl) return null;
  const compile = (type, text) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, text);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  };
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, `#version 300 es
    in float x, y, r, group;
    uniform float scale, ly;
    uniform vec2 size;
    uniform vec3 palette[16];
    out vec3 colour;
    out float radius;
    void main() {
      vec2 p = vec2(x * scale, (ly - y) * scale);            // pixels, y down
      gl_Position = vec4(2.0 * p.x / size.x - 1.0, 1.0 - 2.0 * p.y / size.y, 0.0, 1.0);
      radius = r * scale;
      gl_PointSize = max(2.0 * radius, 1.0);
      colour = palette[int(group)];
    }`));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, `#version 300 es
    precision mediump float;
    in vec3 colour;
    in float radius;
    out vec4 pixel;
    void main() {
      // A point of at most 2 pixels stays a square (the disk covers its pixel); larger ones are circles.
      if (radius > 1.0 && length(gl_PointCoord - 0.5) > 0.5) discard;
      pixel = vec4(colour, 1.0);
    }`));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) return null;
  const maxPoint = gl.getParameter(gl.ALIASED_POINT_SIZE_RANGE)[1];
  // A software implementation (SwiftShader, llvmpipe) is read back into the page's software compositing
  // every frame, which costs more than writing the pixels directly: the page then prefers its 2D path.
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = String(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER));
  const columns = ['x', 'y', 'r', 'group'].map((name) => ({ loc: gl.getAttribLocation(program, name), buf: gl.createBuffer() }));
  const u = (name) => gl.getUniformLocation(program, name);
  const uniforms = { scale: u('scale'), ly: u('ly'), size: u('size'), palette: u('palette') };
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  columns.forEach((c, k) => {
    gl.bindBuffer(gl.ARRAY_BUFFER, c.buf);
    gl.enableVertexAttribArray(c.loc);
    if (k < 3) gl.vertexAttribPointer(c.loc, 1, gl.FLOAT, false, 0, 0);
    else gl.vertexAttribPointer(c.loc, 1, gl.UNSIGNED_BYTE, false, 0, 0);  // the group, read as a float
  });
  const rgb = (hex) => { const v = parseInt(hex.slice(1), 16); return [(v >> 16) / 255, ((v >> 8) & 255) / 255, (v & 255) / 255]; };

  return {
    renderer,
    software: /swiftshader|llvmpipe|softpipe|software/i.test(renderer),
    clear() {
      gl.clearColor(0, 0, 0, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
    },
    // Draws the disks, or returns false (nothing drawn) when one is larger than the largest point.
    draw(f, groups, palette, scale, rmax) {
      if (2 * rmax * scale > maxPoint) return false;
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.clearColor(0, 0, 0, 1);
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.useProgram(program);
      gl.bindVertexArray(vao);
      [f.x, f.y, f.r, groups].forEach((data, k) => {
        gl.bindBuffer(gl.ARRAY_BUFFER, columns[k].buf);
        gl.bufferData(gl.ARRAY_BUFFER, data, gl.STREAM_DRAW);
      });
      gl.uniform1f(uniforms.scale, scale);
      gl.uniform1f(uniforms.ly, f.info.ly);
      gl.uniform2f(uniforms.size, canvas.width, canvas.height);
      const colours = new Float32Array(48);
      palette.slice(0, 16).forEach((hex, k) => colours.set(rgb(hex), 3 * k));
      gl.uniform3fv(uniforms.palette, colours);
      gl.drawArrays(gl.POINTS, 0, f.n);
      return true;
    },
  };
}
