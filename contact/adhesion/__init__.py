"""Adhesive normal contact: interaction laws, the adhesive solve, approach-retraction cycles."""
