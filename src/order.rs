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

/// An entry of a `BinaryHeap` that pops the least `key` first; among equal keys the least
/// `tie`, then the least `id` (keys compare as `f64::total_cmp` orders them). `item` rides along
/// and is not compared.
#[derive(Debug, Clone, Copy)]
pub struct Least<T> {
    /// What orders the heap: the least pops first.
    pub key: f64,
    /// The first tie-break.
    pub tie: f64,
    /// The second tie-break, making the order total.
    pub id: usize,
    /// The payload.
    pub item: T,
}

impl<T> PartialEq for Least<T> {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == std::cmp::Ordering::Equal
    }
}
impl<T> Eq for Least<T> {}
impl<T> PartialOrd for Least<T> {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}
impl<T> Ord for Least<T> {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        o.key.total_cmp(&self.key).then(o.tie.total_cmp(&self.tie)).then(o.id.cmp(&self.id))
    }
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

    /// A heap of [`Least`] pops by key, then tie, then id.
    #[test]
    fn least_pops_first() {
        let mut heap = std::collections::BinaryHeap::new();
        for (key, tie, id) in [(2.0, 0.0, 0), (1.0, 5.0, 3), (1.0, 5.0, 1), (1.0, -1.0, 9), (3.0, 0.0, 0)] {
            heap.push(Least { key, tie, id, item: id });
        }
        let popped: Vec<usize> = std::iter::from_fn(|| heap.pop().map(|e| e.item)).collect();
        assert_eq!(popped, vec![9, 1, 3, 0, 0]);
    }
}
