//! First-generation SimMechanics XML front end. See `parse`.
