//! The node arena of the VORRT tree.
//!
//! Every node holds ownship's state and its time; the targets' states at that
//! time are predicted in closed form from the root (`vorrt_jfs::LinearTrack`)
//! rather than stored, and the encounters in force are kept in one flat
//! array, `targets` entries a node. Buffers are sized once per plan and
//! reused, so growing the tree allocates nothing.

use crate::config::NearestIndex;
use glam::DVec2;
use rstar::RTree;
use rstar::primitives::GeomWithData;
use vorrt_colregs::EncounterLatch;

type IndexedPoint = GeomWithData<[f64; 2], u32>;

/// The tree of joint states.
#[derive(Debug, Default)]
pub struct Tree {
    /// Ownship's position at each node, metres.
    pub positions: Vec<DVec2>,
    /// Ownship's course on the segment into each node, radians.
    pub courses: Vec<f64>,
    /// Time of each node, seconds.
    pub times: Vec<f64>,
    /// Parent of each node (the root is its own parent).
    pub parents: Vec<u32>,
    /// Encounters in force at each node: `latches[node * targets + target]`.
    pub latches: Vec<Option<EncounterLatch>>,
    targets: usize,
    index: NearestIndex,
    rtree: RTree<IndexedPoint>,
}

impl Tree {
    /// Empties the tree and sizes its buffers for `capacity` nodes of `targets` targets.
    pub fn reset(&mut self, capacity: usize, targets: usize, index: NearestIndex) {
        self.positions.clear();
        self.courses.clear();
        self.times.clear();
        self.parents.clear();
        self.latches.clear();
        self.positions.reserve(capacity);
        self.courses.reserve(capacity);
        self.times.reserve(capacity);
        self.parents.reserve(capacity);
        self.latches.reserve(capacity * targets);
        self.targets = targets;
        self.index = index;
        self.rtree = RTree::new();
    }

    /// Number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Whether the tree has no node.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Adds a node and returns its index; `latches` holds one entry per target.
    pub fn push(
        &mut self,
        position_m: DVec2,
        course_rad: f64,
        time_s: f64,
        parent: u32,
        latches: &[Option<EncounterLatch>],
    ) -> u32 {
        debug_assert_eq!(latches.len(), self.targets);
        let index = self.positions.len() as u32;
        self.positions.push(position_m);
        self.courses.push(course_rad);
        self.times.push(time_s);
        self.parents.push(parent);
        self.latches.extend_from_slice(latches);
        if self.index == NearestIndex::RTree {
            self.rtree
                .insert(IndexedPoint::new([position_m.x, position_m.y], index));
        }
        index
    }

    /// The encounters in force at `node`.
    #[must_use]
    pub fn latches_of(&self, node: u32) -> &[Option<EncounterLatch>] {
        let start = node as usize * self.targets;
        &self.latches[start..start + self.targets]
    }

    /// The node nearest to `point_m` (Algorithm 2, `getClosestNode`); ties go
    /// to the older node. `None` only for an empty tree.
    #[must_use]
    pub fn nearest(&self, point_m: DVec2) -> Option<u32> {
        match self.index {
            NearestIndex::Linear => {
                let mut best = None;
                let mut best_distance = f64::INFINITY;
                for (index, position) in self.positions.iter().enumerate() {
                    let distance = position.distance_squared(point_m);
                    if distance < best_distance {
                        best_distance = distance;
                        best = Some(index as u32);
                    }
                }
                best
            }
            NearestIndex::RTree => self
                .rtree
                .nearest_neighbor(&[point_m.x, point_m.y])
                .map(|entry| entry.data),
        }
    }

    /// The branch from the root to `node`, root first.
    #[must_use]
    pub fn branch(&self, node: u32) -> Vec<u32> {
        let mut branch = vec![node];
        let mut current = node;
        while self.parents[current as usize] != current {
            current = self.parents[current as usize];
            branch.push(current);
        }
        branch.reverse();
        branch
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_and_rtree_agree() {
        let mut linear = Tree::default();
        let mut indexed = Tree::default();
        linear.reset(64, 0, NearestIndex::Linear);
        indexed.reset(64, 0, NearestIndex::RTree);
        for i in 0..50u32 {
            let position = DVec2::new(f64::from(i * 37 % 101), f64::from(i * 53 % 97));
            linear.push(position, 0.0, 0.0, 0, &[]);
            indexed.push(position, 0.0, 0.0, 0, &[]);
        }
        for probe in [
            DVec2::new(3.3, 7.1),
            DVec2::new(90.0, 12.0),
            DVec2::new(50.5, 50.5),
        ] {
            let a = linear.nearest(probe).unwrap();
            let b = indexed.nearest(probe).unwrap();
            assert_eq!(
                linear.positions[a as usize].distance(probe),
                indexed.positions[b as usize].distance(probe)
            );
        }
    }

    #[test]
    fn branch_runs_root_first() {
        let mut tree = Tree::default();
        tree.reset(4, 0, NearestIndex::Linear);
        tree.push(DVec2::ZERO, 0.0, 0.0, 0, &[]);
        tree.push(DVec2::X, 0.0, 1.0, 0, &[]);
        tree.push(DVec2::Y, 0.0, 2.0, 1, &[]);
        assert_eq!(tree.branch(2), vec![0, 1, 2]);
    }
}
