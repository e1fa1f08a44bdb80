"""The screens: one arcade.View each."""
