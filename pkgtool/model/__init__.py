"""The immutable package model: files parsed without importing or executing anything."""
