//! The cablenav web page's entry point; the page itself is the `cablenav_web` library. The same
//! module started in a Web Worker serves jobs instead (`cablenav_web::worker`).

fn main() {
    if cablenav_web::worker::in_worker() {
        cablenav_web::worker::serve();
    } else {
        cablenav_web::start();
    }
}
