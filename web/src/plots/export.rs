//! Exports: CSV and JSON text of intervals and paths (plain functions, tested natively), and the
//! browser side — saving a file, copying text, rendering an SVG element to PNG.

use crate::logic::{fmt_exact, StripModel};
use cablenav::model::Pose;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// The sections and boundaries as CSV: `kind,t0,t1,tau0,tau1` rows, then a blank line and
/// `t,tau,constraint,enters` rows. Numbers round-trip exactly.
pub fn intervals_csv(model: &StripModel) -> String {
    let mut out = String::from("kind,t0,t1,tau0,tau1\n");
    for s in &model.sections {
        let (a, b) = s.tau.map_or((String::new(), String::new()), |[a, b]| (fmt_exact(a), fmt_exact(b)));
        out += &format!("{},{},{},{a},{b}\n", s.kind.as_str(), fmt_exact(s.t0), fmt_exact(s.t1));
    }
    out += "\nt,tau,constraint,enters\n";
    for t in &model.ticks {
        out += &format!("{},{},{},{}\n", fmt_exact(t.t), fmt_exact(t.tau), csv_field(&t.constraint), t.enters);
    }
    out
}

/// A CSV field, quoted when it holds a comma, quote or line break.
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) { format!("\"{}\"", s.replace('"', "\"\"")) } else { s.to_string() }
}

/// Poses as CSV: the parameter, the position, tilt-and-torsion angles (rad) and the quaternion.
pub fn poses_csv(param: &str, poses: &[(f64, Pose)]) -> String {
    let mut out = format!("{param},x,y,z,phi,theta,sigma,qw,qx,qy,qz\n");
    for (t, p) in poses {
        let c = p.coords();
        let q = p.quaternion();
        let cells: Vec<String> = [*t].into_iter().chain(c).chain(q).map(fmt_exact).collect();
        out += &cells.join(",");
        out.push('\n');
    }
    out
}

/// Poses as JSON: `[{"<param>": .., "position": [..], "tilt_torsion": [..], "quaternion": [..]}]`.
pub fn poses_json(param: &str, poses: &[(f64, Pose)]) -> String {
    let rows: Vec<serde_json::Value> = poses
        .iter()
        .map(|(t, p)| {
            let c = p.coords();
            serde_json::json!({ param: t, "position": [c[0], c[1], c[2]], "tilt_torsion": [c[3], c[4], c[5]], "quaternion": p.quaternion() })
        })
        .collect();
    serde_json::to_string_pretty(&rows).unwrap_or_default()
}

/// Offers `bytes` as a file download named `name`.
pub fn save(name: &str, mime: &str, bytes: &[u8]) {
    let Some(doc) = web_sys::window().and_then(|w| w.document()) else { return };
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let props = web_sys::BlobPropertyBag::new();
    props.set_type(mime);
    let Ok(blob) = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &props) else { return };
    save_blob(&doc, name, &blob);
}

fn save_blob(doc: &web_sys::Document, name: &str, blob: &web_sys::Blob) {
    let Ok(url) = web_sys::Url::create_object_url_with_blob(blob) else { return };
    if let Ok(a) = doc.create_element("a").map(|e| e.unchecked_into::<web_sys::HtmlAnchorElement>()) {
        a.set_href(&url);
        a.set_download(name);
        if let Some(body) = doc.body() {
            let _ = body.append_child(&a);
            a.click();
            let _ = body.remove_child(&a);
        }
    }
    let _ = web_sys::Url::revoke_object_url(&url);
}

/// Puts `text` on the clipboard (where the browser allows it).
pub fn copy(text: &str) {
    if let Some(w) = web_sys::window() {
        let _ = w.navigator().clipboard().write_text(text);
    }
}

/// The SVG element as a standalone file's text.
pub fn svg_text(svg: &web_sys::Element) -> String {
    let mut text = svg.outer_html();
    if !text.contains("xmlns=") {
        text = text.replacen("<svg", "<svg xmlns=\"http://www.w3.org/2000/svg\"", 1);
    }
    text
}

/// Renders the SVG element at twice its viewBox size to a PNG and offers it as `name`.
pub fn save_svg_as_png(svg: &web_sys::Element, name: &str, width: f64, height: f64) {
    let Some(doc) = web_sys::window().and_then(|w| w.document()) else { return };
    let text = svg_text(svg);
    let parts = js_sys::Array::of1(&JsValue::from_str(&text));
    let props = web_sys::BlobPropertyBag::new();
    props.set_type("image/svg+xml");
    let Ok(blob) = web_sys::Blob::new_with_str_sequence_and_options(&parts, &props) else { return };
    let Ok(url) = web_sys::Url::create_object_url_with_blob(&blob) else { return };
    let Ok(img) = web_sys::HtmlImageElement::new() else { return };
    let name = name.to_string();
    let (img2, url2) = (img.clone(), url.clone());
    let onload = Closure::once_into_js(move || {
        let _ = web_sys::Url::revoke_object_url(&url2);
        let Ok(canvas) = doc.create_element("canvas").map(|e| e.unchecked_into::<web_sys::HtmlCanvasElement>()) else { return };
        canvas.set_width((width * 2.0) as u32);
        canvas.set_height((height * 2.0) as u32);
        let Ok(Some(ctx)) = canvas.get_context("2d") else { return };
        let ctx: web_sys::CanvasRenderingContext2d = ctx.unchecked_into();
        ctx.set_fill_style_str("#ffffff");
        ctx.fill_rect(0.0, 0.0, width * 2.0, height * 2.0);
        let _ = ctx.draw_image_with_html_image_element_and_dw_and_dh(&img2, 0.0, 0.0, width * 2.0, height * 2.0);
        save_canvas(&canvas, &name);
    });
    img.set_onload(Some(onload.unchecked_ref()));
    img.set_src(&url);
}

/// Offers a canvas's pixels as a PNG file.
pub fn save_canvas(canvas: &web_sys::HtmlCanvasElement, name: &str) {
    let Some(doc) = web_sys::window().and_then(|w| w.document()) else { return };
    let name = name.to_string();
    let done = Closure::once_into_js(move |blob: Option<web_sys::Blob>| {
        if let Some(blob) = blob {
            save_blob(&doc, &name, &blob);
        }
    });
    let _ = canvas.to_blob(done.unchecked_ref());
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::logic::{SectionKind, Section, Tick};
    use nalgebra::Vector3;

    #[test]
    fn intervals_round_trip_through_csv() {
        let model = StripModel {
            sections: vec![
                Section { kind: SectionKind::Infeasible, t0: 0.0, t1: 0.6948514220984694, tau: Some([0.0, 0.7]) },
                Section { kind: SectionKind::Uncertain, t0: 0.6948514220984694, t1: 1.0, tau: None },
            ],
            ticks: vec![Tick { t: 0.6948514220984694, tau: 0.7, constraint: "cable 3 - crown, \"x\"".into(), enters: "feasible", label: String::new() }],
            gaps: vec![],
            duration: None,
        };
        let csv = intervals_csv(&model);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], "kind,t0,t1,tau0,tau1");
        assert_eq!(lines[1], "infeasible,0.0,0.6948514220984694,0.0,0.7");
        assert_eq!(lines[2], "uncertain,0.6948514220984694,1.0,,");
        assert_eq!(lines[3], "");
        assert_eq!(lines[5], "0.6948514220984694,0.7,\"cable 3 - crown, \"\"x\"\"\",feasible");
        assert_eq!(lines[1].split(',').nth(2).unwrap().parse::<f64>().unwrap(), 0.6948514220984694);
    }

    #[test]
    fn poses_export_with_coordinates_and_quaternions() {
        let p = Pose::from_tilt_torsion(Vector3::new(1.0, 2.0, 3.0), [0.5, 0.25, -0.125]);
        let csv = poses_csv("t", &[(0.5, p)]);
        let row: Vec<f64> = csv.lines().nth(1).unwrap().split(',').map(|x| x.parse().unwrap()).collect();
        assert_eq!(row.len(), 11);
        assert_eq!(row[..4], [0.5, 1.0, 2.0, 3.0]);
        assert_eq!(row[4..7], p.coords()[3..]);
        assert_eq!(row[7..], p.quaternion());
        let json: serde_json::Value = serde_json::from_str(&poses_json("t", &[(0.5, p)])).unwrap();
        assert_eq!(json[0]["t"], 0.5);
        assert_eq!(json[0]["position"][2], 3.0);
        assert_eq!(json[0]["quaternion"].as_array().unwrap().len(), 4);
    }
}
