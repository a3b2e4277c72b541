//! The page's side: starting a worker for a job and receiving its replies. Each long job gets its
//! own worker (the browser keeps the compiled module cached), so cancelling is terminating it: the
//! page never waits for a planner to notice a flag. A stream of short jobs (the plots along the
//! followed path) shares one [`Resident`] worker instead.

use super::protocol::{decode_reply, encode_job, Job, Reply};
use leptos::prelude::{GetValue, LocalStorage, SetValue, StoredValue, UpdateValue};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A job running in its worker; dropping it (or [`Running::cancel`]) terminates the worker.
pub struct Running {
    worker: web_sys::Worker,
    _onmessage: Closure<dyn FnMut(web_sys::MessageEvent)>,
    _onerror: Closure<dyn FnMut(web_sys::Event)>,
}

impl Running {
    /// Stops the job now.
    pub fn cancel(&self) {
        self.worker.terminate();
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        self.worker.terminate();
    }
}

/// Drops `run` after the current event (a worker's message handler may not drop itself).
pub fn retire(run: Running) {
    leptos::prelude::set_timeout(move || drop(run), std::time::Duration::ZERO);
}

/// How many workers to use for work that splits (slice rows): the machine's logical cores,
/// at least 1 and at most 8.
pub fn parallelism() -> usize {
    web_sys::window().map_or(1.0, |w| w.navigator().hardware_concurrency()).clamp(1.0, 8.0) as usize
}

/// `res` rows split into at most `workers` consecutive blocks of nearly equal size, as
/// `[from, to)` pairs covering `0..res`.
pub fn row_blocks(res: usize, workers: usize) -> Vec<[usize; 2]> {
    let k = workers.clamp(1, res.max(1));
    (0..k).map(|b| [b * res / k, (b + 1) * res / k]).filter(|r| r[0] < r[1]).collect()
}

/// The absolute URL of the page's JS module, from the preload link that both builds write into
/// the page (`<link rel="modulepreload">`).
fn module_url() -> Result<String, String> {
    let doc = web_sys::window().and_then(|w| w.document()).ok_or("no document")?;
    let base = doc.base_uri().ok().flatten().ok_or("no base URI")?;
    let rel = doc
        .query_selector("link[rel=modulepreload][href$='.js']")
        .ok()
        .flatten()
        .and_then(|e| e.get_attribute("href"))
        .ok_or("the page has no modulepreload link to start a worker from")?;
    web_sys::Url::new_with_base(&rel, &base).map(|u| u.href()).map_err(|_| format!("bad URL {rel}"))
}

thread_local! {
    /// The workers' script as a Blob URL, made once for the page (every worker starts from it).
    static SCRIPT: std::cell::OnceCell<String> = const { std::cell::OnceCell::new() };
}

/// The workers' script: the page's module, started again from the page's compiled wasm module
/// (posted first, so the worker neither fetches nor compiles it again); `main` finds no window
/// and serves jobs. A Blob URL made at the first start and kept for the page's life, so a start
/// costs the page no new Blob (it was ~5 ms of the main thread per start).
fn worker_script() -> Result<String, String> {
    if let Some(url) = SCRIPT.with(|s| s.get().cloned()) {
        return Ok(url);
    }
    let js = module_url()?;
    let source = format!("import init from {js:?};\nself.onmessage = (e) => {{ self.onmessage = null; init({{ module_or_path: e.data }}); }};\n");
    let parts = js_sys::Array::of1(&JsValue::from_str(&source));
    let kind = web_sys::BlobPropertyBag::new();
    kind.set_type("text/javascript");
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &kind).map_err(|e| format!("{e:?}"))?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(|e| format!("{e:?}"))?;
    SCRIPT.with(|s| {
        let _ = s.set(url.clone());
    });
    Ok(url)
}

/// Starts `job` in a new worker; `on_reply` gets its replies (the last one final: not
/// [`Reply::Progress`]). A worker that fails to start or crashes gives a [`Reply::Failed`].
pub fn start(job: &Job, mut on_reply: impl FnMut(Reply) + 'static) -> Result<Running, String> {
    let script_url = worker_script()?;
    let options = web_sys::WorkerOptions::new();
    options.set_type(web_sys::WorkerType::Module);
    let worker = web_sys::Worker::new_with_options(&script_url, &options).map_err(|e| format!("cannot start a worker: {e:?}"))?;

    let message = JsValue::from_str(&encode_job(1, job));
    let (w, failed) = (worker.clone(), std::rc::Rc::new(std::cell::Cell::new(false)));
    let on_error_failed = failed.clone();
    let reply = std::rc::Rc::new(std::cell::RefCell::new(move |r: Reply| on_reply(r)));
    let reply2 = reply.clone();
    let onmessage = Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |ev: web_sys::MessageEvent| {
        let text = ev.data().as_string().unwrap_or_default();
        match decode_reply(&text) {
            None => {
                let _ = w.post_message(&message);
            }
            Some(Ok(envelope)) => (reply.borrow_mut())(envelope.body),
            Some(Err(e)) => (reply.borrow_mut())(Reply::Failed { error: format!("bad reply from the worker: {e}") }),
        }
    });
    let onerror = Closure::<dyn FnMut(web_sys::Event)>::new(move |ev: web_sys::Event| {
        if on_error_failed.replace(true) {
            return;
        }
        let why = ev.dyn_ref::<web_sys::ErrorEvent>().map_or_else(|| "the worker failed".to_string(), |e| e.message());
        (reply2.borrow_mut())(Reply::Failed { error: format!("worker: {why}") });
    });
    worker.set_onmessage(Some(onmessage.as_ref().unchecked_ref()));
    worker.set_onerror(Some(onerror.as_ref().unchecked_ref()));
    worker.post_message(&wasm_bindgen::module()).map_err(|e| format!("cannot send the module to the worker: {e:?}"))?;
    Ok(Running { worker, _onmessage: onmessage, _onerror: onerror })
}

/// One worker kept for a stream of short jobs (the plots along the followed path), so that a new
/// job costs the page no new worker (6–9 ms of the main thread each). Jobs are numbered; a new one
/// supersedes the one before, whose replies are then dropped (it is not cut short: the worker
/// answers its jobs in turn). A worker that fails is replaced at the next job; dropping the
/// `Resident` terminates its worker.
#[derive(Default)]
pub struct Resident {
    inner: std::rc::Rc<std::cell::RefCell<ResidentInner>>,
}

#[derive(Default)]
struct ResidentInner {
    worker: Option<web_sys::Worker>,
    /// The worker has loaded the module and takes jobs.
    ready: bool,
    /// The newest job's message, kept until the worker is ready.
    waiting: Option<String>,
    /// The newest job's number: only its replies are passed on.
    current: u32,
    on_reply: Option<Box<dyn FnMut(Reply)>>,
    /// The worker's message and error handlers, kept alive with it.
    handlers: Option<Handlers>,
}

/// A worker's `onmessage` and `onerror` closures.
type Handlers = (Closure<dyn FnMut(web_sys::MessageEvent)>, Closure<dyn FnMut(web_sys::Event)>);

impl Drop for ResidentInner {
    fn drop(&mut self) {
        if let Some(w) = &self.worker {
            w.terminate();
        }
    }
}

impl Resident {
    /// No worker yet (it starts with the first job).
    pub fn new() -> Resident {
        Resident::default()
    }

    /// Sends `job`, superseding the one before; `on_reply` gets its replies (the last one final).
    pub fn send(&self, job: &Job, on_reply: impl FnMut(Reply) + 'static) -> Result<(), String> {
        let mut r = self.inner.borrow_mut();
        r.current = r.current.wrapping_add(1);
        let message = encode_job(r.current, job);
        r.on_reply = Some(Box::new(on_reply));
        if r.worker.is_none() {
            drop(r);
            self.spawn()?;
            r = self.inner.borrow_mut();
        }
        if r.ready {
            let sent = r.worker.as_ref().map(|w| w.post_message(&JsValue::from_str(&message)));
            if let Some(Err(e)) = sent {
                return Err(format!("cannot send the job to the worker: {e:?}"));
            }
        } else {
            r.waiting = Some(message);
        }
        Ok(())
    }

    /// Stops the worker now (the current job with it); the next job starts a new one.
    pub fn stop(&self) {
        let mut r = self.inner.borrow_mut();
        r.current = r.current.wrapping_add(1);
        r.on_reply = None;
        r.waiting = None;
        r.ready = false;
        if let Some(w) = r.worker.take() {
            w.terminate();
        }
        r.handlers = None;
    }

    /// Drops the current job's replies from now on.
    pub fn forget(&self) {
        let mut r = self.inner.borrow_mut();
        r.current = r.current.wrapping_add(1);
        r.on_reply = None;
        r.waiting = None;
    }

    /// Starts the worker and wires its messages to the current job.
    fn spawn(&self) -> Result<(), String> {
        let script_url = worker_script()?;
        let options = web_sys::WorkerOptions::new();
        options.set_type(web_sys::WorkerType::Module);
        let worker = web_sys::Worker::new_with_options(&script_url, &options).map_err(|e| format!("cannot start a worker: {e:?}"))?;
        let weak = std::rc::Rc::downgrade(&self.inner);
        let onmessage = Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |ev: web_sys::MessageEvent| {
            let Some(inner) = weak.upgrade() else { return };
            let text = ev.data().as_string().unwrap_or_default();
            let reply = match decode_reply(&text) {
                None => {
                    let mut r = inner.borrow_mut();
                    r.ready = true;
                    if let (Some(m), Some(w)) = (r.waiting.take(), r.worker.as_ref()) {
                        let _ = w.post_message(&JsValue::from_str(&m));
                    }
                    return;
                }
                Some(Ok(envelope)) if envelope.id == inner.borrow().current => envelope.body,
                Some(Ok(_)) => return, // a superseded job's
                Some(Err(e)) => Reply::Failed { error: format!("bad reply from the worker: {e}") },
            };
            Resident::pass(&inner, reply);
        });
        let weak = std::rc::Rc::downgrade(&self.inner);
        let onerror = Closure::<dyn FnMut(web_sys::Event)>::new(move |ev: web_sys::Event| {
            let Some(inner) = weak.upgrade() else { return };
            let why = ev.dyn_ref::<web_sys::ErrorEvent>().map_or_else(|| "the worker failed".to_string(), |e| e.message());
            {
                // replaced at the next job
                let mut r = inner.borrow_mut();
                if let Some(w) = r.worker.take() {
                    w.terminate();
                }
                r.ready = false;
            }
            Resident::pass(&inner, Reply::Failed { error: format!("worker: {why}") });
        });
        worker.set_onmessage(Some(onmessage.as_ref().unchecked_ref()));
        worker.set_onerror(Some(onerror.as_ref().unchecked_ref()));
        worker.post_message(&wasm_bindgen::module()).map_err(|e| format!("cannot send the module to the worker: {e:?}"))?;
        let mut r = self.inner.borrow_mut();
        r.worker = Some(worker);
        r.ready = false;
        r.handlers = Some((onmessage, onerror));
        Ok(())
    }

    /// Calls the current job's callback with `reply`, outside the borrow (the callback may send).
    fn pass(inner: &std::rc::Rc<std::cell::RefCell<ResidentInner>>, reply: Reply) {
        let (job, callback) = {
            let mut r = inner.borrow_mut();
            (r.current, r.on_reply.take())
        };
        if let Some(mut f) = callback {
            f(reply);
            let mut r = inner.borrow_mut();
            if r.current == job && r.on_reply.is_none() {
                r.on_reply = Some(f);
            }
        }
    }
}

/// The page's hold on one fan-out run ([`start_all`]) at a time: its workers, and a generation
/// that a new run, Cancel or the run's end moves on, so the replies of an older run are ignored.
/// Copyable into the run's callbacks.
#[derive(Clone, Copy)]
pub struct FanOut {
    running: StoredValue<Vec<Running>, LocalStorage>,
    generation: StoredValue<u32>,
}

impl FanOut {
    /// Nothing running.
    pub fn new() -> FanOut {
        FanOut { running: StoredValue::new_local(Vec::new()), generation: StoredValue::new(0) }
    }

    /// Stops the run going, if any: its workers are terminated and its late replies ignored.
    /// Returns the generation of the next run.
    pub fn stop(&self) -> u32 {
        self.generation.update_value(|g| *g += 1);
        self.running.update_value(|r| std::mem::take(r).iter().for_each(Running::cancel));
        self.generation.get_value()
    }

    /// Whether run `this` is still the current one (not stopped, replaced or ended).
    pub fn is_current(&self, this: u32) -> bool {
        self.generation.get_value() == this
    }

    /// Keeps the workers [`start_all`] started for the current run.
    pub fn hold(&self, started: Vec<Running>) {
        self.running.set_value(started);
    }

    /// The end of run `this` (for `start_all`'s `done`): `finish` takes its result only if the
    /// run is still current; then the run is over (later replies are ignored) and its workers are
    /// retired after this event.
    pub fn finish(&self, this: u32, finish: impl FnOnce()) {
        if !self.is_current(this) {
            return;
        }
        finish();
        self.generation.update_value(|g| *g += 1);
        self.running.update_value(|r| std::mem::take(r).into_iter().for_each(retire));
    }
}

impl Default for FanOut {
    fn default() -> Self {
        FanOut::new()
    }
}

/// Runs `jobs` at once, one worker each (work split into blocks), and joins their answers:
/// `part` reads a job's final reply into its part (`Err` for a failure; progress replies and other
/// kinds are passed to it too and may be ignored with `None`), `progress` gets the mean of the
/// jobs' progress fractions and the number of parts in after each reply, and `done` gets the parts
/// in job order once all are in, or the first error (once). Returns the running workers (cancel
/// or drop them to stop); if one cannot start, those started are cancelled and the error returned.
pub fn start_all<T: 'static>(
    jobs: &[Job],
    part: impl Fn(Reply) -> Option<Result<T, String>> + 'static,
    progress: impl Fn(f64, usize) + 'static,
    done: impl Fn(Result<Vec<T>, String>) + 'static,
) -> Result<Vec<Running>, String> {
    struct Join<T> {
        parts: Vec<Option<T>>,
        fractions: Vec<f64>,
        over: bool,
    }
    let n = jobs.len();
    let join = std::rc::Rc::new(std::cell::RefCell::new(Join { parts: (0..n).map(|_| None).collect(), fractions: vec![0.0; n], over: false }));
    let (part, progress, done) = (std::rc::Rc::new(part), std::rc::Rc::new(progress), std::rc::Rc::new(done));
    let mut started = Vec::with_capacity(n);
    for (k, job) in jobs.iter().enumerate() {
        let (join, part, progress, done) = (join.clone(), part.clone(), progress.clone(), done.clone());
        let on_reply = move |reply: Reply| {
            if join.borrow().over {
                return;
            }
            if let Reply::Progress { fraction, .. } = &reply {
                join.borrow_mut().fractions[k] = *fraction;
            }
            let got = part(reply);
            let finished = {
                let mut j = join.borrow_mut();
                match got {
                    None => None,
                    Some(Err(e)) => {
                        j.over = true;
                        Some(Err(e))
                    }
                    Some(Ok(p)) => {
                        j.parts[k] = Some(p);
                        j.fractions[k] = 1.0;
                        if j.parts.iter().all(Option::is_some) {
                            j.over = true;
                            Some(Ok(j.parts.iter_mut().filter_map(Option::take).collect()))
                        } else {
                            None
                        }
                    }
                }
            };
            match finished {
                Some(result) => done(result),
                None => {
                    let (mean, count) = {
                        let j = join.borrow();
                        (j.fractions.iter().sum::<f64>() / n as f64, j.parts.iter().filter(|p| p.is_some()).count())
                    };
                    progress(mean, count);
                }
            }
        };
        match start(job, on_reply) {
            Ok(w) => started.push(w),
            Err(e) => {
                started.iter().for_each(Running::cancel);
                return Err(e);
            }
        }
    }
    Ok(started)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn row_blocks_cover_the_rows_once() {
        assert_eq!(row_blocks(10, 3), [[0, 3], [3, 6], [6, 10]]);
        assert_eq!(row_blocks(2, 8), [[0, 1], [1, 2]], "no empty block");
        assert_eq!(row_blocks(64, 1), [[0, 64]]);
        for (res, k) in [(256, 7), (33, 4), (1, 2)] {
            let b = row_blocks(res, k);
            assert!(b[0][0] == 0 && b.last().unwrap()[1] == res && b.windows(2).all(|w| w[0][1] == w[1][0]), "{b:?}");
        }
    }
}
