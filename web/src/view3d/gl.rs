//! The WebGL2 side of the 3-D view: one shader program (lit or unlit by the vertex normal), three
//! vertex buffers (solid, lines, translucent) and a draw call per pass.

use super::scene::{Geometry, STRIDE};
use glam::Mat4;
use wasm_bindgen::JsCast;
use web_sys::{HtmlCanvasElement, WebGl2RenderingContext as Gl, WebGlBuffer, WebGlProgram, WebGlUniformLocation, WebGlVertexArrayObject};

const VERTEX: &str = r#"#version 300 es
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_colour;
uniform mat4 u_mvp;
out vec3 v_normal;
out vec4 v_colour;
void main() {
  v_normal = a_normal;
  v_colour = a_colour;
  gl_Position = u_mvp * vec4(a_pos, 1.0);
}
"#;

const FRAGMENT: &str = r#"#version 300 es
precision mediump float;
in vec3 v_normal;
in vec4 v_colour;
out vec4 colour;
void main() {
  float light = 1.0;
  if (dot(v_normal, v_normal) > 0.0) {
    vec3 n = normalize(v_normal);
    // two lights, double-sided, so every face reads whatever its winding
    light = 0.38 + 0.47 * abs(dot(n, normalize(vec3(0.4, 0.3, 0.85)))) + 0.2 * abs(dot(n, normalize(vec3(-0.6, 0.7, 0.2))));
  }
  colour = vec4(v_colour.rgb * min(light, 1.0), v_colour.a);
}
"#;

/// One vertex buffer and how many vertices it holds.
struct Pass {
    vao: WebGlVertexArrayObject,
    buffer: WebGlBuffer,
    count: i32,
}

/// One layer of geometry: its three passes.
struct Layer {
    solid: Pass,
    lines: Pass,
    translucent: Pass,
}

/// The backdrop's layer (uploaded when the scenario's static parts change).
pub const BACKDROP: usize = 0;
/// The moving parts' layer (uploaded at every change of what is shown).
pub const MOVING: usize = 1;

/// The renderer of one canvas.
pub struct Renderer {
    gl: Gl,
    program: WebGlProgram,
    mvp: WebGlUniformLocation,
    layers: [Layer; 2],
}

fn compile(gl: &Gl, kind: u32, src: &str) -> Result<web_sys::WebGlShader, String> {
    let shader = gl.create_shader(kind).ok_or("cannot create a shader")?;
    gl.shader_source(&shader, src);
    gl.compile_shader(&shader);
    if gl.get_shader_parameter(&shader, Gl::COMPILE_STATUS).as_bool() == Some(true) {
        Ok(shader)
    } else {
        Err(gl.get_shader_info_log(&shader).unwrap_or_default())
    }
}

fn pass(gl: &Gl) -> Result<Pass, String> {
    let vao = gl.create_vertex_array().ok_or("cannot create a vertex array")?;
    let buffer = gl.create_buffer().ok_or("cannot create a buffer")?;
    gl.bind_vertex_array(Some(&vao));
    gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&buffer));
    let stride = (STRIDE * 4) as i32;
    for (loc, size, offset) in [(0u32, 3, 0), (1, 3, 12), (2, 4, 24)] {
        gl.enable_vertex_attrib_array(loc);
        gl.vertex_attrib_pointer_with_i32(loc, size, Gl::FLOAT, false, stride, offset);
    }
    gl.bind_vertex_array(None);
    Ok(Pass { vao, buffer, count: 0 })
}

impl Renderer {
    /// A renderer on `canvas`, or why WebGL2 is not available.
    pub fn new(canvas: &HtmlCanvasElement) -> Result<Renderer, String> {
        let options = js_sys::Object::new();
        // keep the last frame readable (exports, tests reading pixels) and smooth edges
        js_sys::Reflect::set(&options, &"preserveDrawingBuffer".into(), &true.into()).map_err(|_| "options")?;
        js_sys::Reflect::set(&options, &"antialias".into(), &true.into()).map_err(|_| "options")?;
        let gl: Gl = canvas
            .get_context_with_context_options("webgl2", &options)
            .map_err(|_| "WebGL2 context creation failed".to_string())?
            .ok_or("this browser has no WebGL2")?
            .dyn_into()
            .map_err(|_| "not a WebGL2 context")?;
        let program = gl.create_program().ok_or("cannot create a program")?;
        gl.attach_shader(&program, &compile(&gl, Gl::VERTEX_SHADER, VERTEX)?);
        gl.attach_shader(&program, &compile(&gl, Gl::FRAGMENT_SHADER, FRAGMENT)?);
        gl.link_program(&program);
        if gl.get_program_parameter(&program, Gl::LINK_STATUS).as_bool() != Some(true) {
            return Err(gl.get_program_info_log(&program).unwrap_or_default());
        }
        let mvp = gl.get_uniform_location(&program, "u_mvp").ok_or("no u_mvp")?;
        let layer = |gl: &Gl| -> Result<Layer, String> { Ok(Layer { solid: pass(gl)?, lines: pass(gl)?, translucent: pass(gl)? }) };
        let layers = [layer(&gl)?, layer(&gl)?];
        Ok(Renderer { gl, program, mvp, layers })
    }

    /// Replaces the geometry of layer `layer` ([`BACKDROP`] or [`MOVING`]).
    pub fn upload(&mut self, layer: usize, g: &Geometry) {
        let gl = &self.gl;
        let Some(l) = self.layers.get_mut(layer) else { return };
        for (p, data) in [(&mut l.solid, &g.solid), (&mut l.lines, &g.lines), (&mut l.translucent, &g.translucent)] {
            gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&p.buffer));
            // a copy into a JS Float32Array: no view into wasm memory outlives this call
            let array = js_sys::Float32Array::from(data.as_slice());
            gl.buffer_data_with_array_buffer_view(Gl::ARRAY_BUFFER, &array, Gl::STATIC_DRAW);
            p.count = (data.len() / STRIDE) as i32;
        }
    }

    /// Draws both layers with `view_projection` into a `width` × `height` pixel canvas: the opaque
    /// triangles and lines first, the translucent triangles last.
    pub fn draw(&self, view_projection: Mat4, width: i32, height: i32) {
        let gl = &self.gl;
        gl.viewport(0, 0, width, height);
        gl.clear_color(0.984, 0.988, 0.992, 1.0);
        gl.clear(Gl::COLOR_BUFFER_BIT | Gl::DEPTH_BUFFER_BIT);
        gl.enable(Gl::DEPTH_TEST);
        gl.use_program(Some(&self.program));
        gl.uniform_matrix4fv_with_f32_array(Some(&self.mvp), false, &view_projection.to_cols_array());
        gl.disable(Gl::BLEND);
        gl.depth_mask(true);
        for l in &self.layers {
            self.draw_pass(&l.solid, Gl::TRIANGLES);
            self.draw_pass(&l.lines, Gl::LINES);
        }
        gl.enable(Gl::BLEND);
        gl.blend_func(Gl::SRC_ALPHA, Gl::ONE_MINUS_SRC_ALPHA);
        gl.depth_mask(false);
        for l in &self.layers {
            self.draw_pass(&l.translucent, Gl::TRIANGLES);
        }
        gl.depth_mask(true);
    }

    fn draw_pass(&self, p: &Pass, mode: u32) {
        if p.count > 0 {
            self.gl.bind_vertex_array(Some(&p.vao));
            self.gl.draw_arrays(mode, 0, p.count);
            self.gl.bind_vertex_array(None);
        }
    }
}
