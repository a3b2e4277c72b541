//! The XML toolkit both CASPR readers share: parsing (a DTD allowed), the root element checked,
//! element children, numbers read from text, the cable set and a cable's properties; errors name
//! the file (`bodies`, `cables`, `trajectories`) and give the line.

use roxmltree::{Document, Node, ParsingOptions};

use crate::error::{Error, Result};

/// Parses XML; CASPR files start with a `<!DOCTYPE ... SYSTEM "...dtd">`, which is allowed (an
/// external DTD is never loaded).
pub(super) fn parse_xml(text: &str) -> std::result::Result<Document<'_>, roxmltree::Error> {
    Document::parse_with_options(text, ParsingOptions { allow_dtd: true, ..ParsingOptions::default() })
}

/// Parses `text` as XML for `file`, with the root element `root`.
pub(super) fn document<'a>(file: &str, text: &'a str, root: &str) -> Result<Document<'a>> {
    let doc = parse_xml(text).map_err(|e| Error::new(file, format!("not well-formed XML: {e}")))?;
    let got = doc.root_element().tag_name().name();
    if got != root {
        return Err(Error::new(
            file,
            format!("the root element is <{got}>, expected <{root}> (is this the CASPR {file} file?)"),
        ));
    }
    Ok(doc)
}

/// "line N" of a node, for messages.
pub(super) fn line(node: Node) -> String {
    format!("line {}", node.document().text_pos_at(node.range().start).row)
}

/// Element children of `node` called `tag`.
pub(super) fn children<'a, 'i>(node: Node<'a, 'i>, tag: &'a str) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children().filter(move |c| c.is_element() && c.tag_name().name() == tag)
}

/// The trajectory elements of a CASPR trajectories file's root, each with its `id` (empty when
/// none): the children of every `<joint_trajectories>`; another group (operational-space
/// trajectories) is skipped with a note.
pub(super) fn joint_trajectories<'a, 'i>(root: Node<'a, 'i>, notes: &mut Vec<String>) -> Vec<(Node<'a, 'i>, &'a str)> {
    let mut out = Vec::new();
    for group in root.children().filter(|c| c.is_element()) {
        if group.tag_name().name() != "joint_trajectories" {
            notes.push(format!("{}: <{}> skipped: only joint-space trajectories are imported", line(group), group.tag_name().name()));
            continue;
        }
        out.extend(group.children().filter(|c| c.is_element()).map(|node| (node, node.attribute("id").unwrap_or_default())));
    }
    out
}

/// The one child `tag` of `node`, if any.
pub(super) fn child<'a, 'i>(node: Node<'a, 'i>, tag: &'a str) -> Option<Node<'a, 'i>> {
    children(node, tag).next()
}

/// `N` finite numbers separated by white space, from `text` at `node` (for messages).
pub(super) fn numbers<const N: usize>(file: &str, node: Node, what: &str, text: &str) -> Result<[f64; N]> {
    let v = numbers_n(file, node, what, text, N)?;
    let mut out = [0.0; N];
    out.copy_from_slice(&v);
    Ok(out)
}

/// `n` finite numbers separated by white space, from `text` at `node` (for messages): a joint's
/// coordinates, as many as its type has.
pub(super) fn numbers_n(file: &str, node: Node, what: &str, text: &str, n: usize) -> Result<Vec<f64>> {
    let parts: Vec<&str> = text.split_whitespace().collect();
    if parts.len() != n {
        return Err(Error::new(file, format!("{}: {what} needs {n} numbers, got {:?}", line(node), text.trim())));
    }
    parts
        .iter()
        .map(|p| {
            p.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| Error::new(file, format!("{}: {what}: {p:?} is not a finite number", line(node))))
        })
        .collect()
}

/// The text of child `tag` of `node` as `N` numbers; `None` when there is no such child.
pub(super) fn child_numbers<const N: usize>(file: &str, node: Node, tag: &str) -> Result<Option<[f64; N]>> {
    match child(node, tag) {
        None => Ok(None),
        Some(c) => numbers(file, c, &format!("<{tag}>"), c.text().unwrap_or_default()).map(Some),
    }
}

/// The cable set to import: the one `chosen` (by its id), else the `default_cable_set`, or the
/// only one.
pub(super) fn cable_set<'a, 'i>(root: Node<'a, 'i>, chosen: Option<&str>) -> Result<Node<'a, 'i>> {
    const FILE: &str = "cables";
    let sets: Vec<Node> = children(root, "cable_set").collect();
    if let Some(id) = chosen {
        let ids: Vec<&str> = sets.iter().filter_map(|s| s.attribute("id")).collect();
        return sets.iter().find(|s| s.attribute("id") == Some(id)).copied().ok_or_else(|| {
            Error::new("cable_set", format!("the cables file has no cable set {id:?}; its sets are {ids:?}"))
        });
    }
    Ok(match root.attribute("default_cable_set") {
        Some(id) => sets.iter().find(|s| s.attribute("id") == Some(id)).copied().ok_or_else(|| {
            Error::new(FILE, format!("default_cable_set {id:?} names no <cable_set id=...> in the file"))
        })?,
        None => match sets.as_slice() {
            [only] => *only,
            _ => return Err(Error::new(FILE, format!("{} cable sets and no default_cable_set to choose one", sets.len()))),
        },
    })
}

/// A cable's `force_min`, `force_max` and `diameter` properties, where given.
pub(super) fn properties(cable: Node) -> Result<[Option<f64>; 3]> {
    let props = child(cable, "properties");
    let prop = |tag: &str| -> Result<Option<f64>> {
        match props {
            Some(p) => Ok(child_numbers::<1>("cables", p, tag)?.map(|[x]| x)),
            None => Ok(None),
        }
    };
    Ok([prop("force_min")?, prop("force_max")?, prop("diameter")?])
}
