//! The cablenav web page's entry point; the page itself is the `cablenav_web` library.

fn main() {
    cablenav_web::start();
}
