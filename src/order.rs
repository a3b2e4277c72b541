//! Sorting by a number, with one copy of the standard library's sort for all of it: each
//! `sort_by` with a closure of its own is another whole copy of the sorting code in the page's
//! wasm (docs/benchmarks.md, "Page weight"), so the core's and the page's numeric sorts go
//! through [`sort_by_key`].

/// The positions 0..n in increasing order of `key` (equal keys in increasing position; keys
/// compare as `f64::total_cmp` orders them).
pub fn order(n: usize, key: &dyn Fn(usize) -> f64) -> Vec<usize> {
    let mut keyed: Vec<(f64, usize)> = (0..n).map(|i| (key(i), i)).collect();
    keyed.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    keyed.into_iter().map(|(_, i)| i).collect()
}

/// Sorts `v` in increasing order of `key`, keeping equal keys in their order (a stable sort).
pub fn sort_by_key<T>(v: &mut Vec<T>, key: impl Fn(&T) -> f64) {
    let order = order(v.len(), &|i| key(&v[i]));
    let mut slots: Vec<Option<T>> = v.drain(..).map(Some).collect();
    v.extend(order.into_iter().filter_map(|i| slots[i].take()));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sorted by key, stable among equal keys, NaN and signed zeros where total_cmp puts them.
    #[test]
    fn sorts_stably_by_key() {
        let mut v = vec![(3.0, 'a'), (1.0, 'b'), (3.0, 'c'), (-0.0, 'd'), (0.0, 'e'), (f64::NAN, 'f'), (1.0, 'g')];
        sort_by_key(&mut v, |p| p.0);
        let tags: String = v.iter().map(|p| p.1).collect();
        assert_eq!(tags, "debgacf");
    }
}
