//! [`Table`]: the objects of one kind, addressed by [`Id`], with counted internal references.
//!
//! GL lets an object outlive `delete*` while something still uses it (a buffer attached to a
//! vertex array that is not bound, the current program). A table therefore counts internal
//! references: a deleted object is unreachable through its handle at once, and freed when its
//! last reference goes. A slot's generation changes when it is freed, so a stale [`Id`] never
//! reaches the next object stored there.

use super::Id;

struct Entry<T> {
    generation: u32,
    value: Option<T>,
    deleted: bool,
    refs: u32,
}

/// The objects of one kind, addressed by [`Id`]. Reading is open to the crate; deleting and
/// counting references only to [`Objects`](super::Objects), which keeps them in step.
pub(crate) struct Table<T> {
    entries: Vec<Entry<T>>,
    free: Vec<u32>,
}

impl<T> Default for Table<T> {
    fn default() -> Self {
        Self {
            entries: Vec::new(),
            free: Vec::new(),
        }
    }
}

impl<T> Table<T> {
    /// Stores a new object.
    pub(crate) fn insert(&mut self, value: T) -> Id {
        if let Some(index) = self.free.pop() {
            let e = &mut self.entries[index as usize];
            e.value = Some(value);
            e.deleted = false;
            e.refs = 0;
            Id {
                index,
                generation: e.generation,
            }
        } else {
            let index = self.entries.len() as u32;
            self.entries.push(Entry {
                generation: 0,
                value: Some(value),
                deleted: false,
                refs: 0,
            });
            Id {
                index,
                generation: 0,
            }
        }
    }

    fn entry(&self, id: Id) -> Option<&Entry<T>> {
        self.entries
            .get(id.index as usize)
            .filter(|e| e.generation == id.generation && e.value.is_some())
    }

    fn entry_mut(&mut self, id: Id) -> Option<&mut Entry<T>> {
        self.entries
            .get_mut(id.index as usize)
            .filter(|e| e.generation == id.generation && e.value.is_some())
    }

    /// The object, if it exists and was not deleted (what API calls may use).
    pub(crate) fn get(&self, id: Id) -> Option<&T> {
        self.entry(id)
            .filter(|e| !e.deleted)
            .and_then(|e| e.value.as_ref())
    }

    /// Mutable [`Table::get`].
    pub(crate) fn get_mut(&mut self, id: Id) -> Option<&mut T> {
        self.entry_mut(id)
            .filter(|e| !e.deleted)
            .and_then(|e| e.value.as_mut())
    }

    /// The object even if deleted but still referenced (what internal references may use).
    pub(crate) fn get_any(&self, id: Id) -> Option<&T> {
        self.entry(id).and_then(|e| e.value.as_ref())
    }

    /// Mutable [`Table::get_any`].
    pub(crate) fn get_any_mut(&mut self, id: Id) -> Option<&mut T> {
        self.entry_mut(id).and_then(|e| e.value.as_mut())
    }

    /// Every object stored, deleted but still referenced ones too.
    pub(crate) fn values(&self) -> impl Iterator<Item = &T> {
        self.entries.iter().filter_map(|e| e.value.as_ref())
    }

    /// Whether `id` names a live object.
    pub(crate) fn is_live(&self, id: Id) -> bool {
        self.get(id).is_some()
    }

    /// Marks the object deleted; frees it now if nothing references it. Returns whether the
    /// object was live.
    pub(super) fn delete(&mut self, id: Id) -> bool {
        let Some(e) = self.entry_mut(id) else {
            return false;
        };
        if e.deleted {
            return false;
        }
        e.deleted = true;
        if e.refs == 0 {
            self.free_slot(id);
        }
        true
    }

    /// Counts one more internal reference to `id`.
    pub(super) fn add_ref(&mut self, id: Id) {
        if let Some(e) = self.entry_mut(id) {
            e.refs += 1;
        }
    }

    /// Drops one internal reference to `id`, freeing a deleted object with none left.
    pub(super) fn release(&mut self, id: Id) {
        let Some(e) = self.entry_mut(id) else { return };
        e.refs = e.refs.saturating_sub(1);
        if e.refs == 0 && e.deleted {
            self.free_slot(id);
        }
    }

    /// Replaces the reference held in `slot` by `new`, keeping reference counts right.
    pub(super) fn retarget(&mut self, slot: &mut Option<Id>, new: Option<Id>) {
        if *slot == new {
            return;
        }
        if let Some(n) = new {
            self.add_ref(n);
        }
        if let Some(old) = slot.take() {
            self.release(old);
        }
        *slot = new;
    }

    /// Whether `id` names an object that `delete` marked but that is still referenced (GL's
    /// `DELETE_STATUS`).
    pub(crate) fn is_marked_deleted(&self, id: Id) -> bool {
        self.entry(id).is_some_and(|e| e.deleted)
    }

    /// [`Table::delete`], returning the object if it was freed now (so that the caller can
    /// drop the references it held).
    pub(super) fn delete_freeing(&mut self, id: Id) -> Option<T> {
        let e = self.entry_mut(id)?;
        if e.deleted {
            return None;
        }
        e.deleted = true;
        if e.refs == 0 {
            self.free_slot(id)
        } else {
            None
        }
    }

    /// [`Table::release`], returning the object if it was freed now.
    pub(super) fn release_freeing(&mut self, id: Id) -> Option<T> {
        let e = self.entry_mut(id)?;
        e.refs = e.refs.saturating_sub(1);
        if e.refs == 0 && e.deleted {
            self.free_slot(id)
        } else {
            None
        }
    }

    fn free_slot(&mut self, id: Id) -> Option<T> {
        let e = &mut self.entries[id.index as usize];
        let value = e.value.take();
        e.generation = e.generation.wrapping_add(1);
        e.deleted = false;
        e.refs = 0;
        self.free.push(id.index);
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stale_ids_do_not_alias_new_objects() {
        let mut t = Table::default();
        let a = t.insert(1);
        assert!(t.delete(a));
        let b = t.insert(2);
        assert_eq!(a.index, b.index);
        assert_eq!(t.get(a), None);
        assert_eq!(t.get(b), Some(&2));
    }

    #[test]
    fn referenced_objects_outlive_delete() {
        let mut t = Table::default();
        let a = t.insert(1);
        let mut slot = None;
        t.retarget(&mut slot, Some(a));
        assert!(t.delete(a));
        assert_eq!(t.get(a), None);
        assert_eq!(t.get_any(a), Some(&1));
        t.retarget(&mut slot, None);
        assert_eq!(t.get_any(a), None);
        assert!(!t.delete(a));
    }
}
