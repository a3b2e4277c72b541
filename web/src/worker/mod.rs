//! Heavy work off the main thread. The page's own wasm module is started a second time in a
//! dedicated Web Worker (a module worker whose script imports the page's JS and inits it with the
//! page's already compiled `WebAssembly.Module`, posted to it; `main` sees no `window` and calls
//! [`serve`] instead of mounting the page), so both builds (scripts/build-page.sh and trunk)
//! produce the worker with no extra file and no extra page weight.
//!
//! [`protocol`] holds the jobs and replies (JSON over `postMessage`) and [`jobs`] runs them —
//! plain Rust, tested natively; [`host`] starts workers from the page and [`serve`] is the
//! worker's side. A new job kind is a [`protocol::Job`] variant, its [`protocol::Reply`] and an
//! arm in [`jobs::run`]; a new planner is an arm in [`jobs::planner`].

pub mod host;
pub mod jobs;
pub mod protocol;

use protocol::{Envelope, Reply};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// Whether this code runs in a worker (no `window`).
pub fn in_worker() -> bool {
    web_sys::window().is_none()
}

/// The worker's side: answers each job message with its replies, then a final one. A job runs
/// to its end inside one message event; cancelling is the host terminating the worker.
pub fn serve() {
    console_error_panic_hook::set_once();
    let scope: web_sys::DedicatedWorkerGlobalScope = js_sys::global().unchecked_into();
    let post_scope = scope.clone();
    let post = move |text: String| {
        let _ = post_scope.post_message(&JsValue::from_str(&text));
    };
    let post2 = post.clone();
    let onmessage = Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |ev: web_sys::MessageEvent| {
        let text = ev.data().as_string().unwrap_or_default();
        match protocol::decode_job(&text) {
            Ok(Envelope { id, body }) => jobs::run(body, &mut |reply| post2(protocol::encode_reply(id, &reply)), now_ms),
            Err(e) => post2(protocol::encode_reply(0, &Reply::Failed { error: format!("bad job message: {e}") })),
        }
    });
    scope.set_onmessage(Some(onmessage.as_ref().unchecked_ref()));
    onmessage.forget();
    post(protocol::READY.to_string());
}

/// Milliseconds on the worker's clock.
fn now_ms() -> f64 {
    js_sys::global().unchecked_into::<web_sys::WorkerGlobalScope>().performance().map_or(0.0, |p| p.now())
}
