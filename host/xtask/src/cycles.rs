//! `cargo xtask cycles`: module import cycles inside each crate.
//!
//! A reference from module A to module B (a `use`, or a path `crate::…`, `super::…`, `self::…`
//! or through a child module, in A's own code) is an edge between the two children of their
//! deepest common ancestor that hold A and B: `crate::math::series` using
//! `crate::lanes::F32x4` makes `math → lanes` among the crate root's children. A reference
//! between a module and its own ancestor or descendant (a `mod.rs` re-exporting its children, a
//! `tests` module using `super::*`) is no edge. A cycle is a strongly connected set of two or
//! more siblings: each reaches every other through such edges. Paths are taken as written (a
//! `pub use` re-export is not followed), so an edge says which module a file names.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use syn::visit::Visit;

use crate::rust_files::{module_tree, targets, Module};

/// One reference: the module it is written in, the path's segments, the file and line.
struct Reference {
    from: Vec<String>,
    segments: Vec<String>,
    file: PathBuf,
    line: usize,
}

/// Collects the paths of an item (uses separately, for their trees).
struct Paths<'a> {
    module: &'a Module,
    out: &'a mut Vec<Reference>,
}

impl Paths<'_> {
    fn push(&mut self, segments: Vec<String>, line: usize) {
        self.out.push(Reference {
            from: self.module.path.clone(),
            segments,
            file: self.module.file.clone(),
            line,
        });
    }
}

impl<'ast> Visit<'ast> for Paths<'_> {
    fn visit_path(&mut self, p: &'ast syn::Path) {
        if p.leading_colon.is_none() && p.segments.len() > 1 {
            let segments = p.segments.iter().map(|s| s.ident.to_string()).collect();
            let line = p.segments[0].ident.span().start().line;
            self.push(segments, line);
        }
        syn::visit::visit_path(self, p);
    }

    fn visit_item_use(&mut self, u: &'ast syn::ItemUse) {
        if u.leading_colon.is_none() {
            let mut prefixes = Vec::new();
            use_paths(&u.tree, &mut Vec::new(), &mut prefixes);
            let line = u.use_token.span.start().line;
            for segments in prefixes {
                self.push(segments, line);
            }
        }
    }

    // Nested inline modules are modules of their own (`Module`), not part of this one.
    fn visit_item_mod(&mut self, _: &'ast syn::ItemMod) {}
}

/// The paths a use tree imports, each down to the imported name.
fn use_paths(tree: &syn::UseTree, prefix: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            use_paths(&p.tree, prefix, out);
            prefix.pop();
        }
        syn::UseTree::Name(n) => out.push([prefix.clone(), vec![n.ident.to_string()]].concat()),
        syn::UseTree::Rename(r) => out.push([prefix.clone(), vec![r.ident.to_string()]].concat()),
        syn::UseTree::Glob(_) => out.push(prefix.clone()),
        syn::UseTree::Group(g) => {
            for t in &g.items {
                use_paths(t, prefix, out);
            }
        }
    }
}

/// The module a path written in module `from` names, or `None` when it names no module of the
/// crate (an extern crate, a local item, a name brought in by a `use`).
fn resolve(
    modules: &BTreeSet<Vec<String>>,
    from: &[String],
    segments: &[String],
) -> Option<Vec<String>> {
    let mut base: Vec<String> = from.to_vec();
    let mut rest = segments;
    let mut anchored = false;
    while let Some((first, tail)) = rest.split_first() {
        match first.as_str() {
            "crate" if !anchored => base.clear(),
            "self" if !anchored => {}
            "super" => {
                base.pop()?;
            }
            _ => break,
        }
        anchored = true;
        rest = tail;
    }
    let mut target = base.clone();
    let mut descended = false;
    for segment in rest {
        let mut next = target.clone();
        next.push(segment.clone());
        if modules.contains(&next) {
            target = next;
            descended = true;
        } else {
            break;
        }
    }
    (anchored || descended).then_some(target)
}

/// An edge between two siblings, with one place that makes it.
type Edges = BTreeMap<(String, String), (PathBuf, usize)>;

/// The cycles among the children of each module of one target: (parent, the cycle's siblings,
/// the edges between them).
fn target_cycles(modules: &[Module]) -> Vec<(Vec<String>, Vec<String>, Edges)> {
    let names: BTreeSet<Vec<String>> = modules.iter().map(|m| m.path.clone()).collect();
    let mut references = Vec::new();
    for m in modules {
        let mut v = Paths {
            module: m,
            out: &mut references,
        };
        for item in &m.items {
            v.visit_item(item);
        }
    }
    // Sibling edges, grouped by their parent.
    let mut by_parent: BTreeMap<Vec<String>, Edges> = BTreeMap::new();
    for r in &references {
        let Some(to) = resolve(&names, &r.from, &r.segments) else {
            continue;
        };
        let common = r.from.iter().zip(&to).take_while(|(a, b)| a == b).count();
        if common == r.from.len() || common == to.len() {
            continue; // the same module, an ancestor or a descendant
        }
        by_parent
            .entry(r.from[..common].to_vec())
            .or_default()
            .entry((r.from[common].clone(), to[common].clone()))
            .or_insert((r.file.clone(), r.line));
    }
    let mut cycles = Vec::new();
    for (parent, edges) in by_parent {
        for component in strongly_connected(&edges) {
            let inside: Edges = edges
                .iter()
                .filter(|((a, b), _)| component.contains(a) && component.contains(b))
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect();
            cycles.push((parent.clone(), component, inside));
        }
    }
    cycles
}

/// The strongly connected sets of two or more nodes (Tarjan's algorithm; small graphs).
fn strongly_connected(edges: &Edges) -> Vec<Vec<String>> {
    let nodes: BTreeSet<&String> = edges.keys().flat_map(|(a, b)| [a, b]).collect();
    let reach = |from: &String| -> BTreeSet<String> {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from.clone()];
        while let Some(n) = stack.pop() {
            for ((a, b), _) in edges.iter() {
                if *a == n && seen.insert(b.clone()) {
                    stack.push(b.clone());
                }
            }
        }
        seen
    };
    let reachable: BTreeMap<&String, BTreeSet<String>> =
        nodes.iter().map(|n| (*n, reach(n))).collect();
    let mut done = BTreeSet::new();
    let mut components = Vec::new();
    for n in &nodes {
        if done.contains(*n) {
            continue;
        }
        let component: Vec<String> = nodes
            .iter()
            .filter(|m| reachable[*n].contains(**m) && reachable[**m].contains(*n))
            .map(|m| (*m).clone())
            .collect();
        done.extend(component.iter().cloned());
        if component.len() > 1 {
            components.push(component);
        }
    }
    components
}

/// Every cycle of every target, printed; the count.
pub fn find(root: &Path) -> Result<usize> {
    let mut count = 0;
    let mut seen_roots = BTreeSet::new();
    for target in targets(root)? {
        // A library and its binaries may share files; each root file is read once.
        if !seen_roots.insert(target.root_file.clone()) {
            continue;
        }
        let modules = module_tree(root, &target.root_file)?;
        for (parent, cycle, edges) in target_cycles(&modules) {
            count += 1;
            let parent = if parent.is_empty() {
                "crate root".to_string()
            } else {
                parent.join("::")
            };
            println!(
                "{}: {} (children of {parent})",
                target.label,
                cycle.join(" ↔ ")
            );
            for ((a, b), (file, line)) in edges {
                println!("    {a} → {b}: {}:{line}", file.display());
            }
        }
    }
    Ok(count)
}

pub fn run(root: &Path) -> Result<()> {
    let count = find(root)?;
    if count > 0 {
        bail!("{count} module import cycle(s)");
    }
    println!("no module import cycles");
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(path: &[&str], source: &str) -> Module {
        Module {
            path: path.iter().map(|s| s.to_string()).collect(),
            file: PathBuf::from(format!("{}.rs", path.join("/"))),
            items: syn::parse_file(source).unwrap().items,
        }
    }

    /// Siblings that use each other are a cycle; a module and its parent are not, nor a
    /// one-way use.
    #[test]
    fn finds_sibling_cycles_and_only_those() {
        let modules = vec![
            module(&[], "pub use math::sqrt; fn f() { lanes::x(); }"),
            module(&["math"], "use crate::lanes::F32x4;"),
            module(&["math", "series"], "use super::sqrt;"),
            module(&["lanes"], "pub fn x() { crate::math::series::ln(); }"),
            module(&["film"], "use crate::math::sqrt;"),
        ];
        let cycles = target_cycles(&modules);
        assert_eq!(
            cycles.len(),
            1,
            "{:?}",
            cycles.iter().map(|c| &c.1).collect::<Vec<_>>()
        );
        assert!(cycles[0].0.is_empty());
        assert_eq!(cycles[0].1, vec!["lanes".to_string(), "math".to_string()]);
    }

    #[test]
    fn paths_resolve_from_crate_super_self_and_children() {
        let names: BTreeSet<Vec<String>> = [
            vec![],
            vec!["a".into()],
            vec!["a".into(), "b".into()],
            vec!["c".into()],
        ]
        .into_iter()
        .collect();
        let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
        assert_eq!(
            resolve(&names, &s(&["a", "b"]), &s(&["super", "super", "c", "X"])),
            Some(s(&["c"]))
        );
        assert_eq!(
            resolve(&names, &s(&[]), &s(&["a", "b", "f"])),
            Some(s(&["a", "b"]))
        );
        assert_eq!(
            resolve(&names, &s(&["c"]), &s(&["crate", "Y"])),
            Some(s(&[]))
        );
        assert_eq!(resolve(&names, &s(&["c"]), &s(&["std", "mem"])), None);
    }
}
